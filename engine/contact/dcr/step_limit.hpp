// The DCR step limit, local and relative (docs/contact-time-step.md, "DCR"): over every candidate
// pair of the broad phase (a node and a face, two edges), the step may not let the two features
// approach by more than their gap plus step_fraction times their own shortest edge:
//   dt <= (gap + step_fraction * L_pair) / u_pair,
// u_pair the largest approach speed along the pair's normal of a node of one feature towards a
// node of the other (0 for features that separate or slide: no limit), gap their distance along
// that normal, L_pair the shortest reference edge of the two features. A rigid translation of both
// bodies (u = 0), a fast body far from anything (a large gap) and a small edge elsewhere on the
// surface no longer shorten the step; the projection of a pair that comes into contact stays
// within step_fraction of its own edges.
#pragma once

#include <limits>
#include <vector>

#include "engine/contact/dcr/contact_surface.hpp"
#include "engine/contact/dcr/swept_box_hash.hpp"
#include "engine/core/types.hpp"

namespace ccm::dcr {

struct PairStepLimit {
  double dt = 0.0;  // the smallest allowed step over the pairs (infinity: none approaches)
  int pair = -1;    // candidate index that set it (node-face first, then edge-edge), -1: none
};

// The reference lengths L a pair takes its shortest edge from, computed once per surface: per
// face its shortest edge, per edge its length (X: reference positions).
struct ReferenceLengths {
  std::vector<double> face_shortest_edge;
  std::vector<double> edge;
  double shortest = std::numeric_limits<double>::infinity();  // of all edges
  double longest = 0.0;                                       // of all edges
};
ReferenceLengths reference_lengths(const SurfaceFeatures& f, const std::vector<Vec3>& X);

// x, v: current positions and velocities (indexed by global node id). ceiling: the step the
// caller takes anyway; the result is exact below it, and a pair that cannot allow less than it
// is not evaluated. fastest_node_speed: the largest |v| of the surface nodes (or a bound of it);
// when such a node cannot close step_fraction of the shortest edge within the ceiling, no pair is
// evaluated (dt = infinity, pair = -1).
PairStepLimit pair_step_limit(const SurfaceFeatures& f, const Candidates& c,
                              const ReferenceLengths& lengths, const std::vector<Vec3>& x,
                              const std::vector<Vec3>& v, double step_fraction,
                              double ceiling = std::numeric_limits<double>::infinity(),
                              double fastest_node_speed = std::numeric_limits<double>::infinity());

}  // namespace ccm::dcr
