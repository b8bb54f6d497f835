#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/contact/dcr/broad_phase.hpp"
#include "engine/mesh/gmsh_mesher.hpp"
#include "engine/mesh/structured_box.hpp"

using ccm::ModelMesh;
using ccm::Vec3;
using ccm::dcr::BroadPhase;
using ccm::dcr::Candidates;
using ccm::dcr::EdgeEdgeCandidate;
using ccm::dcr::NodeFaceCandidate;
using ccm::dcr::SurfaceFeatures;

namespace {

const ccm::MaterialParams kRubber{ccm::MaterialModel::neo_hookean, 1e6, 0.45, 1000};

// Two overlapping Gmsh spheres of radius 1 (meshed once per test run).
const ModelMesh& two_spheres() {
  static const ModelMesh mesh = [] {
    ModelMesh m;
    ccm::PrimitiveSpec spec{ccm::PrimitiveKind::sphere};
    spec.radius = 1.0;
    spec.mesh_size = 0.3;
    ccm::add_body(m, "left", kRubber, ccm::mesh_primitive(spec, {}));
    ccm::Placement right;
    right.translation = Vec3(1.7, 0.2, 0.0);
    ccm::add_body(m, "right", kRubber, ccm::mesh_primitive(spec, right));
    return m;
  }();
  return mesh;
}

// A random step: x_start = X + noise, x_end = x_start + displacement.
struct Step {
  std::vector<Vec3> x_start, x_end;
};

Step random_step(const ModelMesh& mesh, double noise, double motion, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Step s;
  for (const Vec3& X : mesh.X) {
    s.x_start.push_back(X + noise * Vec3(u(rng), u(rng), u(rng)));
    s.x_end.push_back(s.x_start.back() + motion * Vec3(u(rng), u(rng), u(rng)));
  }
  return s;
}

// The brute-force reference: every pair, filtered the same way, boxes computed independently.
struct Box {
  Vec3 lo, hi;
};

Box box_of(std::initializer_list<int> nodes, const Step& s, double inflation) {
  Box b{Vec3::Constant(std::numeric_limits<double>::infinity()),
        Vec3::Constant(-std::numeric_limits<double>::infinity())};
  for (int n : nodes) {
    b.lo =
        b.lo.cwiseMin(s.x_start[static_cast<size_t>(n)]).cwiseMin(s.x_end[static_cast<size_t>(n)]);
    b.hi =
        b.hi.cwiseMax(s.x_start[static_cast<size_t>(n)]).cwiseMax(s.x_end[static_cast<size_t>(n)]);
  }
  b.lo.array() -= inflation;
  b.hi.array() += inflation;
  return b;
}

bool overlap(const Box& a, const Box& b) {
  return (a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all();
}

// edge_inflation < 0: the edge boxes take `inflation` as every other box.
Candidates brute_force(const SurfaceFeatures& f, const Step& s, double inflation, bool self_contact,
                       double edge_inflation = -1.0) {
  Candidates c;
  std::vector<Box> faces;
  for (const auto& t : f.faces) faces.push_back(box_of({t[0], t[1], t[2]}, s, inflation));
  for (int i = 0; i < f.n_nodes(); ++i) {
    const int n = f.nodes[static_cast<size_t>(i)];
    const Box bn = box_of({n}, s, inflation);
    for (int j = 0; j < f.n_faces(); ++j) {
      const auto& t = f.faces[static_cast<size_t>(j)];
      if (t[0] == n || t[1] == n || t[2] == n) continue;
      if (!self_contact &&
          f.node_body[static_cast<size_t>(i)] == f.face_body[static_cast<size_t>(j)])
        continue;
      if (overlap(bn, faces[static_cast<size_t>(j)])) c.node_face.push_back({i, j});
    }
  }
  std::vector<Box> edges;
  for (const auto& e : f.edges)
    edges.push_back(box_of({e[0], e[1]}, s, edge_inflation < 0.0 ? inflation : edge_inflation));
  for (int a = 0; a < f.n_edges(); ++a)
    for (int b = a + 1; b < f.n_edges(); ++b) {
      const auto& ea = f.edges[static_cast<size_t>(a)];
      const auto& eb = f.edges[static_cast<size_t>(b)];
      if (ea[0] == eb[0] || ea[0] == eb[1] || ea[1] == eb[0] || ea[1] == eb[1]) continue;
      if (!self_contact &&
          f.edge_body[static_cast<size_t>(a)] == f.edge_body[static_cast<size_t>(b)])
        continue;
      if (overlap(edges[static_cast<size_t>(a)], edges[static_cast<size_t>(b)]))
        c.edge_edge.push_back({a, b});
    }
  return c;
}

bool same(const Candidates& a, const Candidates& b) {
  return a.node_face == b.node_face && a.edge_edge == b.edge_edge;
}

// One fresh search checked against brute force (both lists non-empty); returns its grid entries.
std::size_t search_equals_brute_force(const SurfaceFeatures& f, const Step& step, double inflation,
                                      bool self_contact) {
  BroadPhase bp;
  Candidates got;
  bp.find(f, step.x_start, step.x_end, inflation, self_contact, got);
  const Candidates want = brute_force(f, step, inflation, self_contact);
  CHECK(!want.node_face.empty());
  CHECK(!want.edge_edge.empty());
  CHECK(same(got, want));
  return bp.stats().grid_entries;
}

// The positions at step k of a sequence over the two spheres: the right sphere approaches the
// left one by 0.004 per step and jumps 0.3 towards it after step 30, and every node wobbles by
// up to 0.002 along its own random direction (from `seed`).
class ApproachingSpheres {
 public:
  ApproachingSpheres(const ModelMesh& mesh, unsigned seed) : mesh_(mesh) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (size_t i = 0; i < mesh.X.size(); ++i) wobble_.push_back(Vec3(u(rng), u(rng), u(rng)));
  }
  std::vector<Vec3> operator()(int k) const {
    const double shift = 0.4 - 0.004 * k - (k > 30 ? 0.3 : 0.0);
    std::vector<Vec3> x = mesh_.X;
    for (size_t i = 0; i < x.size(); ++i) {
      x[i] += 0.002 * std::sin(0.3 * k) * wobble_[i];
      if (static_cast<int>(i) >= mesh_.bodies[1].first_node) x[i].x() += shift;
    }
    return x;
  }

 private:
  const ModelMesh& mesh_;
  std::vector<Vec3> wobble_;
};

}  // namespace

TEST_CASE("broad phase equals the brute-force swept-box filter on two spheres", "[dcr]") {
  const ModelMesh& mesh = two_spheres();
  const SurfaceFeatures f =
      ccm::dcr::make_surface_features(mesh, {"left/boundary", "right/boundary"});
  REQUIRE(f.n_faces() > 500);
  const Step step = random_step(mesh, 0.02, 0.05, 1);
  BroadPhase bp;
  Candidates got;

  for (bool self_contact : {false, true}) {
    for (double inflation : {0.0, 0.01, 0.1}) {
      CAPTURE(self_contact, inflation);
      bp.find(f, step.x_start, step.x_end, inflation, self_contact, got);
      const Candidates want = brute_force(f, step, inflation, self_contact);
      CHECK(!want.node_face.empty());
      CHECK(!want.edge_edge.empty());
      CHECK(got.node_face.size() == want.node_face.size());
      CHECK(got.edge_edge.size() == want.edge_edge.size());
      CHECK(same(got, want));
      CHECK(bp.stats().outliers == 0);
    }
  }
}

TEST_CASE("broad phase: adjacency and body exclusions", "[dcr]") {
  const ModelMesh& mesh = two_spheres();
  const SurfaceFeatures f =
      ccm::dcr::make_surface_features(mesh, {"left/boundary", "right/boundary"});
  const Step step = random_step(mesh, 0.0, 0.02, 2);
  BroadPhase bp;
  Candidates self, other;
  bp.find(f, step.x_start, step.x_end, 0.05, true, self);
  bp.find(f, step.x_start, step.x_end, 0.05, false, other);

  auto check_adjacency = [&](const Candidates& c) {
    for (const NodeFaceCandidate& p : c.node_face) {
      const int n = f.nodes[static_cast<size_t>(p.node)];
      for (int v : f.faces[static_cast<size_t>(p.face)]) CHECK(v != n);
    }
    for (const EdgeEdgeCandidate& p : c.edge_edge) {
      CHECK(p.edge_a < p.edge_b);
      const auto& a = f.edges[static_cast<size_t>(p.edge_a)];
      const auto& b = f.edges[static_cast<size_t>(p.edge_b)];
      CHECK((a[0] != b[0] && a[0] != b[1] && a[1] != b[0] && a[1] != b[1]));
    }
  };
  check_adjacency(self);
  check_adjacency(other);

  // Without self contact only pairs across the two bodies remain; with it, pairs within a body
  // (a face and nearby nodes not its own) are candidates too, and every cross pair stays.
  int same_body = 0;
  for (const NodeFaceCandidate& p : other.node_face)
    CHECK(f.node_body[static_cast<size_t>(p.node)] != f.face_body[static_cast<size_t>(p.face)]);
  for (const EdgeEdgeCandidate& p : other.edge_edge)
    CHECK(f.edge_body[static_cast<size_t>(p.edge_a)] != f.edge_body[static_cast<size_t>(p.edge_b)]);
  for (const NodeFaceCandidate& p : self.node_face)
    if (f.node_body[static_cast<size_t>(p.node)] == f.face_body[static_cast<size_t>(p.face)])
      ++same_body;
  CHECK(same_body > 0);
  CHECK(std::includes(self.node_face.begin(), self.node_face.end(), other.node_face.begin(),
                      other.node_face.end(),
                      [](const NodeFaceCandidate& a, const NodeFaceCandidate& b) {
                        return a.node != b.node ? a.node < b.node : a.face < b.face;
                      }));
  CHECK(!other.node_face.empty());
}

TEST_CASE("broad phase: separated bodies give no pairs", "[dcr]") {
  ModelMesh mesh;
  ccm::add_body(mesh, "a", kRubber, ccm::structured_box(Vec3(1, 1, 1), 3, 3, 3));
  ccm::TetMesh b = ccm::structured_box(Vec3(1, 1, 1), 3, 3, 3);
  for (auto& x : b.nodes) x.x() += 1.5;
  ccm::add_body(mesh, "b", kRubber, b);
  const SurfaceFeatures f = ccm::dcr::make_surface_features(mesh, {"a/boundary", "b/boundary"});
  BroadPhase bp;
  Candidates c;
  bp.find(f, mesh.X, mesh.X, 0.1, false, c);
  CHECK(c.node_face.empty());
  CHECK(c.edge_edge.empty());
  // Moving b by 0.35 towards a within the step brings the facing sides into reach.
  std::vector<Vec3> x_end = mesh.X;
  for (int n = mesh.bodies[1].first_node; n < mesh.n_nodes(); ++n)
    x_end[static_cast<size_t>(n)].x() -= 0.35;
  bp.find(f, mesh.X, x_end, 0.1, false, c);
  CHECK(!c.node_face.empty());
  CHECK(!c.edge_edge.empty());
}

TEST_CASE("broad phase: deterministic, whatever ran before", "[dcr]") {
  const ModelMesh& mesh = two_spheres();
  const SurfaceFeatures f =
      ccm::dcr::make_surface_features(mesh, {"left/boundary", "right/boundary"});
  const SurfaceFeatures left = ccm::dcr::make_surface_features(mesh, {"left/boundary"});
  const Step step = random_step(mesh, 0.02, 0.05, 3);
  const Step other = random_step(mesh, 0.1, 0.3, 4);

  BroadPhase fresh, warm;
  Candidates a, b, c;
  fresh.find(f, step.x_start, step.x_end, 0.02, true, a);
  // A warm object that saw a different surface, motion and table size first.
  warm.find(left, other.x_start, other.x_end, 0.2, true, b);
  warm.find(f, other.x_start, other.x_end, 0.0, false, b);
  warm.find(f, step.x_start, step.x_end, 0.02, true, b);
  CHECK(same(a, b));
  warm.find(f, step.x_start, step.x_end, 0.02, true, c);
  CHECK(same(b, c));
  // Sorted and duplicate-free.
  auto nf_less = [](const NodeFaceCandidate& p, const NodeFaceCandidate& q) {
    return p.node != q.node ? p.node < q.node : p.face < q.face;
  };
  auto ee_less = [](const EdgeEdgeCandidate& p, const EdgeEdgeCandidate& q) {
    return p.edge_a != q.edge_a ? p.edge_a < q.edge_a : p.edge_b < q.edge_b;
  };
  CHECK(std::is_sorted(a.node_face.begin(), a.node_face.end(), nf_less));
  CHECK(std::adjacent_find(a.node_face.begin(), a.node_face.end()) == a.node_face.end());
  CHECK(std::is_sorted(a.edge_edge.begin(), a.edge_edge.end(), ee_less));
  CHECK(std::adjacent_find(a.edge_edge.begin(), a.edge_edge.end()) == a.edge_edge.end());
}

TEST_CASE("broad phase: fast outliers and bad positions", "[dcr]") {
  const ModelMesh& mesh = two_spheres();
  const SurfaceFeatures f =
      ccm::dcr::make_surface_features(mesh, {"left/boundary", "right/boundary"});
  Step step = random_step(mesh, 0.02, 0.05, 5);
  // One node flies across both spheres within the step: its features cover far too many cells.
  const int flier = f.nodes[10];
  step.x_end[static_cast<size_t>(flier)] = Vec3(500, 300, -200);
  BroadPhase bp;
  Candidates got;
  bp.find(f, step.x_start, step.x_end, 0.01, true, got);
  CHECK(bp.stats().outliers > 0);
  CHECK(same(got, brute_force(f, step, 0.01, true)));

  step.x_end[static_cast<size_t>(flier)] = Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  CHECK_THROWS_AS(bp.find(f, step.x_start, step.x_end, 0.01, true, got), std::domain_error);
  CHECK_THROWS_WITH(bp.find(f, step.x_start, step.x_end, 0.01, true, got),
                    Catch::Contains(std::to_string(flier)));
}

TEST_CASE("broad phase: cost grows linearly with the surface", "[dcr]") {
  // Plates of 1 x 1 and 2 x 1 (x 0.02) with equal cells: the surface doubles (~10k and ~20k
  // faces). The work counters per feature stay the same; the times are printed, not asserted.
  struct Run {
    int n_faces;
    std::size_t visits, tests, pairs;
    double ms;
  };
  auto run = [](int nx) {
    ModelMesh mesh;
    ccm::add_body(mesh, "plate", kRubber, ccm::structured_box(Vec3(0.02 * nx, 1, 0.02), nx, 50, 1));
    const SurfaceFeatures f = ccm::dcr::make_surface_features(mesh, {"plate/boundary"});
    const Step step = random_step(mesh, 0.002, 0.0004, 6);
    BroadPhase bp;
    Candidates c;
    bp.find(f, step.x_start, step.x_end, 0.0002, true, c);  // warm-up
    const auto t0 = std::chrono::steady_clock::now();
    const int reps = 3;
    for (int r = 0; r < reps; ++r) bp.find(f, step.x_start, step.x_end, 0.0002, true, c);
    const auto t1 = std::chrono::steady_clock::now();
    return Run{f.n_faces(), bp.stats().cell_visits, bp.stats().box_tests,
               c.node_face.size() + c.edge_edge.size(),
               std::chrono::duration<double, std::milli>(t1 - t0).count() / reps};
  };
  const Run small = run(50), large = run(100);
  WARN("broad phase: " << small.n_faces << " faces " << small.ms << " ms (" << small.pairs
                       << " pairs); " << large.n_faces << " faces " << large.ms << " ms ("
                       << large.pairs << " pairs)");
  const double ratio = static_cast<double>(large.n_faces) / small.n_faces;
  CHECK(ratio > 1.9);
  CHECK(static_cast<double>(large.visits) / static_cast<double>(small.visits) ==
        Approx(ratio).epsilon(0.1));
  CHECK(static_cast<double>(large.tests) / static_cast<double>(small.tests) ==
        Approx(ratio).epsilon(0.1));
  CHECK(static_cast<double>(large.pairs) / static_cast<double>(small.pairs) ==
        Approx(ratio).epsilon(0.1));
}

TEST_CASE("broad phase: the cached search equals brute force over a moving sequence",
          "[dcr][broad_phase]") {
  // The right sphere approaches the left one by 0.004 per step (the half skin is about 0.1 here,
  // a quarter of a face box), every node wobbles by up to 0.002 along its own random direction,
  // and at step 30 the right sphere jumps 0.3 towards the left one within a single step: the
  // cache must be reused across steps, rebuilt when a node leaves its allowance, and every step's
  // candidates must equal the all-pairs filter of that step exactly.
  const ModelMesh& mesh = two_spheres();
  const SurfaceFeatures f =
      ccm::dcr::make_surface_features(mesh, {"left/boundary", "right/boundary"});
  const ApproachingSpheres positions(mesh, 7);

  for (bool self_contact : {false, true}) {
    CAPTURE(self_contact);
    BroadPhase bp;
    Candidates got;
    std::size_t pairs = 0;
    for (int k = 0; k < 60; ++k) {
      CAPTURE(k);
      const Step step{positions(k), positions(k + 1)};
      bp.find(f, step.x_start, step.x_end, 0.01, self_contact, got);
      const Candidates want = brute_force(f, step, 0.01, self_contact);
      REQUIRE(same(got, want));
      pairs += got.node_face.size() + got.edge_edge.size();
      if (k == 30) CHECK(bp.stats().rebuilt);  // the jump leaves every allowance box
    }
    CHECK(pairs > 1000);  // the spheres do interact: the comparison is not between empty lists
    CHECK(bp.stats().calls == 60);
    CHECK(bp.stats().rebuilds >= 3);   // the approach outruns the skin more than once
    CHECK(bp.stats().rebuilds <= 20);  // and yet most steps reuse the cache
    // A fresh object on the last step gives the same answer as the warm one.
    BroadPhase fresh;
    Candidates again;
    const Step last{positions(59), positions(60)};
    fresh.find(f, last.x_start, last.x_end, 0.01, self_contact, again);
    bp.find(f, last.x_start, last.x_end, 0.01, self_contact, got);
    CHECK(same(got, again));
  }
}

TEST_CASE("broad phase: edge boxes take their own inflation from the step's largest motion",
          "[dcr][broad_phase]") {
  // The sequence of the test above, with a proximity of 0.05 for nodes and faces and the edge
  // boxes inflated by the proximity halved while its half covers max(floor, 2 m), m the largest
  // side of a swept node box of the step, computed here on its own: every step must equal the
  // all-pairs filter with those two inflations, through cache reuse and rebuilds alike.
  const ModelMesh& mesh = two_spheres();
  const SurfaceFeatures f =
      ccm::dcr::make_surface_features(mesh, {"left/boundary", "right/boundary"});
  const ApproachingSpheres positions(mesh, 11);
  constexpr double kProximity = 0.05, kFloor = 1e-3;
  const ccm::dcr::EdgeInflation edges{.per_motion = 2.0, .floor = kFloor};
  BroadPhase bp;
  Candidates got;
  std::size_t fewer = 0, edge_pairs = 0;
  for (int k = 0; k < 60; ++k) {
    CAPTURE(k);
    const Step step{positions(k), positions(k + 1)};
    double m = 0.0;
    for (int n : f.nodes) {
      const Box b = box_of({n}, step, 0.0);
      m = std::max(m, (b.hi - b.lo).maxCoeff());
    }
    // The proximity halved while its half still covers max(floor, 2 m).
    double edge_inflation = kProximity;
    while (edge_inflation / 2 >= std::max(kFloor, 2.0 * m)) edge_inflation /= 2;
    CHECK(edge_inflation >= std::min(kProximity, 2.0 * m));
    bp.find(f, step.x_start, step.x_end, kProximity, false, got, &edges);
    REQUIRE(bp.stats().step_motion == m);
    REQUIRE(bp.stats().edge_inflation == edge_inflation);
    REQUIRE(same(got, brute_force(f, step, kProximity, false, edge_inflation)));
    const Candidates uniform = brute_force(f, step, kProximity, false);
    CHECK(got.node_face == uniform.node_face);  // nodes and faces keep the proximity
    if (got.edge_edge.size() < uniform.edge_edge.size()) ++fewer;
    edge_pairs += got.edge_edge.size();
  }
  CHECK(edge_pairs > 1000);  // the comparison is not between empty lists
  CHECK(fewer >= 50);        // and the edge inflation does leave pairs out on most steps
  CHECK(bp.stats().rebuilds >= 2);
}

TEST_CASE("broad phase: features far from every other body stay out of the grid search",
          "[dcr][broad_phase]") {
  // The two overlapping spheres and a third one far away (centre x = 10). Without self-contact
  // only features near another body can pair: the grid holds far fewer entries than with
  // self-contact (every feature), and the list still equals brute force.
  static const ModelMesh mesh = [] {
    ModelMesh m = two_spheres();
    ccm::PrimitiveSpec spec{ccm::PrimitiveKind::sphere};
    spec.radius = 1.0;
    spec.mesh_size = 0.3;
    ccm::Placement far;
    far.translation = Vec3(10.0, 0.0, 0.0);
    ccm::add_body(m, "far", kRubber, ccm::mesh_primitive(spec, far));
    return m;
  }();
  const SurfaceFeatures f =
      ccm::dcr::make_surface_features(mesh, {"left/boundary", "right/boundary", "far/boundary"});
  const Step step = random_step(mesh, 0.02, 0.05, 11);
  const std::size_t culled = search_equals_brute_force(f, step, 0.01, false);
  const std::size_t every = search_equals_brute_force(f, step, 0.01, true);
  // The near caps of the two spheres are a minority of the three surfaces' features.
  CHECK(culled * 3 < every);
}

TEST_CASE("broad phase: the skin covers kSkinSteps steps of motion, within its bounds",
          "[dcr][broad_phase]") {
  const ModelMesh& mesh = two_spheres();
  const SurfaceFeatures f =
      ccm::dcr::make_surface_features(mesh, {"left/boundary", "right/boundary"});
  // The median largest side of the face boxes at rest, computed here independently.
  std::vector<double> sides;
  for (const auto& t : f.faces) {
    const Box b = box_of({t[0], t[1], t[2]}, Step{mesh.X, mesh.X}, 0.0);
    sides.push_back((b.hi - b.lo).maxCoeff());
  }
  const auto mid = sides.begin() + static_cast<std::ptrdiff_t>(sides.size() / 2);
  std::nth_element(sides.begin(), mid, sides.end());
  const double extent = *mid;
  auto half_skin = [&](double motion) {  // every node moves by `motion` along x
    std::vector<Vec3> x_end = mesh.X;
    for (Vec3& x : x_end) x.x() += motion;
    BroadPhase bp;
    Candidates c;
    bp.find(f, mesh.X, x_end, 0.01, false, c);
    REQUIRE(bp.stats().rebuilt);
    return bp.stats().half_skin;
  };
  // At rest: the smallest skin.
  CHECK(half_skin(0.0) == Approx(BroadPhase::kMinHalfSkinFraction * extent).epsilon(1e-12));
  // A slow surface: kSkinSteps steps of its motion (0.01, between the bounds 0.005 and 0.033).
  const double slow = 5e-5;
  REQUIRE(BroadPhase::kSkinSteps * slow > 1.5 * BroadPhase::kMinHalfSkinFraction * extent);
  REQUIRE(BroadPhase::kSkinSteps * slow < 0.5 * BroadPhase::kHalfSkinFraction * extent);
  CHECK(half_skin(slow) == Approx(BroadPhase::kSkinSteps * slow).epsilon(1e-9));
  // A fast surface: the largest skin (the face boxes now include the motion).
  const double fast = 0.01;
  const double moved_extent = half_skin(fast) / BroadPhase::kHalfSkinFraction;
  CHECK(moved_extent >= extent);
  CHECK(moved_extent <= extent + fast + 1e-12);
}

TEST_CASE("broad phase: many bodies (one joined hull per body) equal brute force",
          "[dcr][broad_phase]") {
  // Twelve cubes along x, each overlapping its neighbour by a tenth of its side, and a thirteenth
  // far above: more bodies than the search tests one by one, so each feature meets the hull of
  // all other bodies together.
  ModelMesh mesh;
  std::vector<std::string> surfaces;
  for (int b = 0; b < 13; ++b) {
    const std::string name = "cube" + std::to_string(b);
    ccm::add_body(mesh, name, kRubber, ccm::structured_box(Vec3(0.1, 0.1, 0.1), 3, 3, 3));
    const auto& body = mesh.bodies.back();
    const Vec3 shift = b < 12 ? Vec3(0.09 * b, 0.0, 0.0) : Vec3(0.5, 0.0, 5.0);
    for (int n = body.first_node; n < body.first_node + body.n_nodes; ++n)
      mesh.X[static_cast<size_t>(n)] += shift;
    surfaces.push_back(name + "/boundary");
  }
  const SurfaceFeatures f = ccm::dcr::make_surface_features(mesh, surfaces);
  search_equals_brute_force(f, random_step(mesh, 0.001, 0.002, 13), 0.001, false);
}

TEST_CASE("broad phase: each node's skin covers its own motion", "[dcr][broad_phase]") {
  // The right sphere moves 0.002 a step along -x, the left one rests. At the rebuild the right
  // sphere's nodes take the largest skin and the left one's the smallest: when the left sphere
  // then moves by three times the smallest skin (far less than the largest), the cache is
  // rebuilt, and every step still equals the all-pairs filter.
  const ModelMesh& mesh = two_spheres();
  const SurfaceFeatures f =
      ccm::dcr::make_surface_features(mesh, {"left/boundary", "right/boundary"});
  const std::vector<int>& right = mesh.node_sets.at("right");
  auto at = [&](double right_shift, double left_shift) {
    std::vector<Vec3> x = mesh.X;
    for (Vec3& p : x) p.x() += left_shift;
    for (int i : right) x[static_cast<size_t>(i)].x() += -right_shift - left_shift;
    return x;
  };
  BroadPhase bp;
  Candidates got;
  constexpr double kRight = 0.002;
  const Step first{at(0.0, 0.0), at(kRight, 0.0)};
  bp.find(f, first.x_start, first.x_end, 0.01, true, got);
  REQUIRE(bp.stats().rebuilt);
  REQUIRE(same(got, brute_force(f, first, 0.01, true)));
  const double largest = bp.stats().half_skin;
  const double smallest =
      largest * BroadPhase::kMinHalfSkinFraction / BroadPhase::kHalfSkinFraction;
  REQUIRE(largest ==
          Approx(BroadPhase::kHalfSkinFraction / BroadPhase::kMinHalfSkinFraction * smallest));
  REQUIRE(3.0 * smallest < 0.5 * largest);
  // The right sphere's next steps stay inside its skin: no rebuild.
  const Step second{at(kRight, 0.0), at(2 * kRight, 0.0)};
  bp.find(f, second.x_start, second.x_end, 0.01, true, got);
  CHECK_FALSE(bp.stats().rebuilt);
  CHECK(same(got, brute_force(f, second, 0.01, true)));
  // The left sphere moves by three smallest skins: outside its own allowance.
  const Step third{at(2 * kRight, 0.0), at(3 * kRight, 3.0 * smallest)};
  bp.find(f, third.x_start, third.x_end, 0.01, true, got);
  CHECK(bp.stats().rebuilt);
  CHECK(same(got, brute_force(f, third, 0.01, true)));
}
