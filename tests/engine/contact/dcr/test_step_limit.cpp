// The DCR pair step limit (engine/contact/dcr/step_limit.hpp) against its closed form
// dt = (gap + step_fraction L) / u on hand-made pairs: a node above a face and two crossing edges.
// Issue 15 item 3: the former limit used the shortest edge of the whole surface and the
// absolute speed of its fastest node, so a rigid translation or a short edge elsewhere cut the
// step; these cases must not.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
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

// The ceiling (the step the engine takes anyway): below it the limit is exact, and a pair that
// cannot allow less is not evaluated, so a resting contact costs no pair evaluation.
TEST_CASE("DCR step limit: exact below the ceiling, skipped above it", "[dcr][step_limit]") {
  // 40 nodes at random, 10 faces and 15 edges among them, every face against every node
  // (but its own) and every edge against every other (sharing no node) as candidates.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  SurfaceFeatures f;
  std::vector<Vec3> X(40);
  for (size_t n = 0; n < X.size(); ++n) {
    X[n] = 1e-3 * Vec3(unit(rng), unit(rng), unit(rng));
    f.nodes.push_back(static_cast<int>(n));
  }
  for (int k = 0; k < 10; ++k) f.faces.push_back(Triangle{3 * k, 3 * k + 1, 3 * k + 2});
  for (int k = 0; k < 15; ++k) f.edges.push_back({2 * k, 2 * k + 1});
  Candidates c;
  for (int face = 0; face < 10; ++face)
    for (int n = 30; n < 40; ++n) c.node_face.push_back({n, face});
  for (int a = 0; a < 15; ++a)
    for (int b = a + 1; b < 15; ++b) c.edge_edge.push_back({a, b});
  const ReferenceLengths lengths = reference_lengths(f, X);
  auto fastest = [](const std::vector<Vec3>& v) {  // the largest node speed
    double u = 0.0;
    for (const Vec3& w : v) u = std::max(u, w.norm());
    return u;
  };
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Vec3> v(X.size());
    for (Vec3& u : v) u = 10.0 * Vec3(unit(rng), unit(rng), unit(rng));
    const PairStepLimit exact = pair_step_limit(f, c, lengths, X, v, 0.5);
    REQUIRE(std::isfinite(exact.dt));
    for (double ceiling : {0.5 * exact.dt, exact.dt, 1.0001 * exact.dt, 3.0 * exact.dt}) {
      const PairStepLimit capped = pair_step_limit(f, c, lengths, X, v, 0.5, ceiling, fastest(v));
      if (exact.dt < ceiling) {  // bitwise the same limit, set by the same pair
        CHECK(capped.dt == exact.dt);
        CHECK(capped.pair == exact.pair);
      } else {
        CHECK(capped.dt >= ceiling);
      }
    }
  }
  // At rest but for slow drift (1 um/s): every pair allows far more than a 1 us step, and the
  // limit answers without evaluating any (infinity, no pair), while the exact limit is finite.
  std::vector<Vec3> slow(X.size());
  for (Vec3& u : slow) u = 1e-6 * Vec3(unit(rng), unit(rng), unit(rng));
  CHECK(std::isfinite(pair_step_limit(f, c, lengths, X, slow, 0.5).dt));
  const PairStepLimit resting = pair_step_limit(f, c, lengths, X, slow, 0.5, 1e-6, fastest(slow));
  CHECK(resting.dt == kNoLimit);
  CHECK(resting.pair == -1);
}
