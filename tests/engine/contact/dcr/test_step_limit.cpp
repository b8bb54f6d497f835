// The DCR pair step limit (engine/contact/dcr/step_limit.hpp) against its closed form
// dt = (gap + step_fraction L) / u on hand-made pairs: a node above a face and two crossing edges.
// Issue 15 item 3: the former limit used the shortest edge of the whole surface and the
// absolute speed of its fastest node, so a rigid translation or a short edge elsewhere cut the
// step; these cases must not.
#include <catch2/catch.hpp>
#include <limits>
#include <vector>

#include "engine/contact/dcr/step_limit.hpp"

using namespace ccm;
using namespace ccm::dcr;

namespace {

constexpr double kNoLimit = std::numeric_limits<double>::infinity();

// Node 3 at height d above the face (0, 1, 2) in z = 0 (edges 1 and sqrt 2, shortest 1 mm), and a
// far-away short edge (4, 5) of 1 um that is no candidate.
struct NodeAboveFace {
  SurfaceFeatures f;
  Candidates c;
  std::vector<Vec3> X, x, v;
};

NodeAboveFace node_above_face(double d) {
  NodeAboveFace s;
  const double h = 1e-3;
  s.X = {Vec3(0, 0, 0), Vec3(h, 0, 0),       Vec3(0, h, 0), Vec3(0.2 * h, 0.2 * h, d),
         Vec3(1, 1, 1), Vec3(1 + 1e-6, 1, 1)};
  s.x = s.X;
  s.v.assign(s.X.size(), Vec3::Zero());
  s.f.nodes = {0, 1, 2, 3, 4, 5};
  s.f.faces = {Triangle{0, 1, 2}};
  s.f.edges = {{0, 1}, {0, 2}, {1, 2}, {4, 5}};
  s.c.node_face = {{3, 0}};
  return s;
}

}  // namespace

TEST_CASE("DCR step limit: a node approaching a face may close its gap plus half an edge",
          "[dcr][step_limit]") {
  const double d = 2e-4, u = 3.0, fraction = 0.5;
  NodeAboveFace s = node_above_face(d);
  s.v[3] = Vec3(0.7, -0.4, -u);  // the tangential part does not count
  const PairStepLimit r =
      pair_step_limit(s.f, s.c, reference_lengths(s.f, s.X), s.x, s.v, fraction);
  CHECK(r.pair == 0);
  CHECK(r.dt == Approx((d + fraction * 1e-3) / u).epsilon(1e-12));
  // The face moving up at the same speed as the node: the pair approaches at 2u.
  for (int a = 0; a < 3; ++a) s.v[static_cast<size_t>(a)] = Vec3(0, 0, u);
  CHECK(pair_step_limit(s.f, s.c, reference_lengths(s.f, s.X), s.x, s.v, fraction).dt ==
        Approx((d + fraction * 1e-3) / (2 * u)).epsilon(1e-12));
}

TEST_CASE("DCR step limit: translation, separation and a short edge elsewhere do not limit",
          "[dcr][step_limit]") {
  NodeAboveFace s = node_above_face(2e-4);
  for (Vec3& v : s.v) v = Vec3(-50.0, 20.0, -300.0);  // everything translates together
  CHECK(pair_step_limit(s.f, s.c, reference_lengths(s.f, s.X), s.x, s.v, 0.5).dt == kNoLimit);
  s.v[3] += Vec3(0, 0, 1.0);  // the node leaves the face
  CHECK(pair_step_limit(s.f, s.c, reference_lengths(s.f, s.X), s.x, s.v, 0.5).dt == kNoLimit);
  s.v[3] += Vec3(0, 0, -2.0);  // approaches at 1 m/s: the 1 um edge (4, 5) plays no part
  CHECK(pair_step_limit(s.f, s.c, reference_lengths(s.f, s.X), s.x, s.v, 0.5).dt ==
        Approx((2e-4 + 0.5e-3) / 1.0).epsilon(1e-12));
  // A node below the face (penetrated, or on the other side) approaching it from there.
  NodeAboveFace below = node_above_face(-2e-4);
  below.v[3] = Vec3(0, 0, 4.0);
  CHECK(
      pair_step_limit(below.f, below.c, reference_lengths(below.f, below.X), below.x, below.v, 0.5)
          .dt == Approx((2e-4 + 0.5e-3) / 4.0).epsilon(1e-12));
}

TEST_CASE("DCR step limit: two crossing edges, the shorter edge and the fastest node pair",
          "[dcr][step_limit]") {
  // Edge (0, 1) along x, 2 mm; edge (2, 3) along y, 0.5 mm, at height d above it.
  const double d = 1e-4;
  SurfaceFeatures f;
  f.nodes = {0, 1, 2, 3};
  f.edges = {{0, 1}, {2, 3}};
  Candidates c;
  c.edge_edge = {{0, 1}};
  const std::vector<Vec3> X = {Vec3(-1e-3, 0, 0), Vec3(1e-3, 0, 0), Vec3(0, -0.25e-3, d),
                               Vec3(0, 0.25e-3, d)};
  std::vector<Vec3> v(4, Vec3::Zero());
  v[2] = Vec3(0, 0, -1.0);
  v[3] = Vec3(0, 0, -2.0);  // the edge also rotates: its faster end counts
  v[0] = Vec3(0, 0, 0.5);
  const PairStepLimit r = pair_step_limit(f, c, reference_lengths(f, X), X, v, 0.5);
  CHECK(r.pair == 0);
  CHECK(r.dt == Approx((d + 0.5 * 0.5e-3) / 2.5).epsilon(1e-12));
}
