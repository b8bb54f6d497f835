// The skips that make resting DCR contact cheap never drop a contact the full path finds
// (docs/hard-scenes.md, "Resting contact"):
//  - the node-face prefilter (ccd_prefilter.hpp) lets through every pair the exact CCD reports
//    and every persistent contact (within the proximity distance of the face at the end of the
//    step, its projection inside the face); without the proximity term, every crossing;
//  - the pair distance cache (pair_distance_cache.hpp) proves a pair apart only when the fresh
//    prefilter of that step rejects it, over random motions of many steps, with pairs leaving
//    and re-entering the candidate lists and re-anchorings.
#include <array>
#include <catch2/catch.hpp>
#include <random>
#include <vector>

#include "engine/contact/dcr/ccd.hpp"
#include "engine/contact/dcr/ccd_prefilter.hpp"
#include "engine/contact/dcr/pair_distance_cache.hpp"

using namespace ccm;

namespace {

// The persistent-contact test of DcrContact::node_face_contact (barycentric tolerance 1e-6).
bool pdc_test_projects_inside(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a, r = p - a;
  const double d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2);
  const double r1 = r.dot(e1), r2 = r.dot(e2), det = d11 * d22 - d12 * d12;
  if (!(det > 0.0)) return false;
  const double wb = (d22 * r1 - d12 * r2) / det, wc = (d11 * r2 - d12 * r1) / det;
  constexpr double tol = 1e-6;
  return wb >= -tol && wc >= -tol && 1.0 - wb - wc >= -tol;
}

// What the full path of DcrContact::node_face_contact decides, without the prefilter.
bool pdc_test_node_face_contact(const Vec3& p0, const Vec3& a0, const Vec3& b0, const Vec3& c0,
                                const Vec3& p1, const Vec3& a1, const Vec3& b1, const Vec3& c1,
                                double proximity) {
  if (dcr::node_face_volume(p0, a0, b0, c0) < 0.0) return false;
  if (dcr::node_face_ccd(p0, a0, b0, c0, p1, a1, b1, c1, 1e-6)) return true;
  const double g1 = dcr::node_face_volume(p1, a1, b1, c1);
  const double third_area = (b1 - a1).cross(c1 - a1).norm() / 6.0;
  return g1 >= 0.0 && g1 <= proximity * third_area && pdc_test_projects_inside(p1, a1, b1, c1);
}

}  // namespace

TEST_CASE("DCR resting contact: the node-face prefilter never skips a contact", "[dcr][hard]") {
  // Closed forms of the point-triangle distance: above the face, beyond an edge, a vertex.
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  CHECK(dcr::point_triangle_distance(Vec3(0.2, 0.2, 0.3), a, b, c) == Approx(0.3).epsilon(1e-14));
  CHECK(dcr::point_triangle_distance(Vec3(0.5, -0.4, 0.3), a, b, c) == Approx(0.5).epsilon(1e-14));
  CHECK(dcr::point_triangle_distance(Vec3(-3, -4, 0), a, b, c) == Approx(5.0).epsilon(1e-14));
  CHECK(dcr::point_triangle_distance(Vec3(1, 1, 0), a, b, c) ==
        Approx(std::sqrt(0.5)).epsilon(1e-14));

  std::mt19937 rng(615);
  std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 1.0);
  auto random_vec = [&](double scale) -> Vec3 {
    const double x = u(rng), y = u(rng), z = u(rng);
    return Vec3(x, y, z) * scale;
  };
  const double proximity = 0.1;
  int contacts = 0, persistent = 0, skipped = 0, ccd_skipped = 0, off_plane = 0;
  for (int trial = 0; trial < 40000; ++trial) {
    const Vec3 a0 = random_vec(0.3), b0 = a0 + Vec3(1, 0, 0) + random_vec(0.3),
               c0 = a0 + Vec3(0, 1, 0) + random_vec(0.3);
    // The node near the face's plane, over the face or beside it.
    const Vec3 n = (b0 - a0).cross(c0 - a0).normalized();
    const double s = 1.4 * w(rng) - 0.2, t = (1.2 - s) * w(rng) - 0.1;
    const Vec3 p0 = a0 + s * (b0 - a0) + t * (c0 - a0) + (0.3 * w(rng) - 0.02) * n;
    const double reach = trial % 3 == 0 ? 0.002 : (trial % 3 == 1 ? 0.05 : 0.3);
    const Vec3 p1 = p0 + random_vec(reach), a1 = a0 + random_vec(reach),
               b1 = b0 + random_vec(reach), c1 = c0 + random_vec(reach);
    const bool contact = pdc_test_node_face_contact(p0, a0, b0, c0, p1, a1, b1, c1, proximity);
    const bool may = dcr::node_face_may_touch(p0, a0, b0, c0, p1, a1, b1, c1, proximity);
    // Without the proximity term the filter stands for the CCD alone: it passes every crossing.
    const bool may_cross = dcr::node_face_may_touch(p0, a0, b0, c0, p1, a1, b1, c1, 0.0);
    const bool crosses = dcr::node_face_ccd(p0, a0, b0, c0, p1, a1, b1, c1, 1e-6).has_value();
    if (contact) {
      ++contacts;
      if (!crosses) ++persistent;
      CHECK(may);
    }
    if (crosses && dcr::node_face_volume(p0, a0, b0, c0) >= 0.0) CHECK(may_cross);
    // The test from the CCD's cubic (ccd_prefilter.hpp): wherever the node stays off the face's
    // plane, the CCD finds no hit.
    if (dcr::node_stays_off_face_plane(p0, a0, b0, c0, p1, a1, b1, c1)) {
      ++off_plane;
      CHECK(!crosses);
    }
    if (!may) ++skipped;
    if (may && !may_cross) ++ccd_skipped;
  }
  INFO("contacts " << contacts << ", persistent " << persistent << ", skipped " << skipped
                   << ", CCD skipped after the persistent test " << ccd_skipped
                   << ", off the plane " << off_plane);
  CHECK(off_plane > 5000);  // the cubic's test decides many pairs too
  CHECK(persistent > 1000);
  CHECK(contacts - persistent > 1000);
  CHECK(skipped > 5000);      // the filter decides many pairs without the CCD
  CHECK(ccd_skipped > 1000);  // and, without the proximity term, many more CCDs
}

TEST_CASE("DCR resting contact: the pair distance cache only skips what the prefilter rejects",
          "[dcr][hard]") {
  // 40 nodes (global ids 0..39, all on the surface) in random positions in a 1 m box; faces are
  // triples and edges pairs of them, and the candidates all node-face and edge pairs without a
  // common node (sorted, as the broad phase gives them). Over 300 steps the nodes move by small
  // random steps (some larger, some jumps past the re-anchoring distance); each step a random
  // fifth of the candidates is left out of the lists. Wherever the cache proves a pair apart,
  // the fresh prefilter of that step must reject it; wherever the node-free form proves it, so
  // does the per-node form (it is the weaker bound).
  std::mt19937 rng(616);
  std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 1.0);
  constexpr int kNodes = 40;
  std::vector<Vec3> x0(kNodes), x1(kNodes);
  for (Vec3& p : x0) p = Vec3(w(rng), w(rng), w(rng));
  std::vector<std::array<int, 3>> faces;
  std::vector<std::array<int, 2>> edges;
  for (int i = 0; i + 2 < kNodes; i += 3) faces.push_back({i, i + 1, i + 2});
  for (int i = 0; i + 1 < kNodes; i += 2) edges.push_back({i, i + 1});
  for (int i = 1; i + 1 < kNodes; i += 4) edges.push_back({i, i + 1});
  std::vector<int> nodes(kNodes);
  for (int i = 0; i < kNodes; ++i) nodes[static_cast<size_t>(i)] = i;
  const double proximity = 0.02, reanchor = 0.05;
  dcr::PairDistanceCache cache(kNodes, reanchor);
  long proved = 0, rejected = 0, recorded = 0, proved_for_any = 0;
  for (int step = 0; step < 300; ++step) {
    const double scale = step % 50 == 49 ? 0.08 : (step % 7 == 0 ? 0.01 : 0.001);
    for (int i = 0; i < kNodes; ++i) {
      const auto k = static_cast<size_t>(i);
      x1[k] = x0[k] + scale * Vec3(u(rng), u(rng), u(rng));
    }
    dcr::Candidates c;
    for (int n = 0; n < kNodes; ++n)
      for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
        const auto& t = faces[static_cast<size_t>(f)];
        if (t[0] == n || t[1] == n || t[2] == n || w(rng) < 0.2) continue;
        c.node_face.push_back({n, f});
      }
    for (int ea = 0; ea < static_cast<int>(edges.size()); ++ea)
      for (int eb = ea + 1; eb < static_cast<int>(edges.size()); ++eb) {
        const auto& A = edges[static_cast<size_t>(ea)];
        const auto& B = edges[static_cast<size_t>(eb)];
        if (A[0] == B[0] || A[0] == B[1] || A[1] == B[0] || A[1] == B[1] || w(rng) < 0.2) continue;
        c.edge_edge.push_back({ea, eb});
      }
    cache.prepare(c, nodes, x0, x1);
    const size_t n_nf = c.node_face.size();
    for (size_t k = 0; k < n_nf + c.edge_edge.size(); ++k) {
      bool may;
      std::array<int, 4> ids;
      double d, slack;
      if (k < n_nf) {
        const int p = c.node_face[k].node;
        const auto& t = faces[static_cast<size_t>(c.node_face[k].face)];
        ids = {p, t[0], t[1], t[2]};
        auto X0 = [&](int j) { return x0[static_cast<size_t>(ids[static_cast<size_t>(j)])]; };
        auto X1 = [&](int j) { return x1[static_cast<size_t>(ids[static_cast<size_t>(j)])]; };
        may = dcr::node_face_may_touch(X0(0), X0(1), X0(2), X0(3), X1(0), X1(1), X1(2), X1(3),
                                       proximity);
        d = dcr::point_triangle_distance(X0(0), X0(1), X0(2), X0(3));
        slack = dcr::face_slack(X0(1), X0(2), X0(3));
        if (cache.proves_apart_for_any_nodes(k, proximity)) {  // the weaker, node-free form
          ++proved_for_any;
          CHECK(cache.proves_apart(k, ids, 1, proximity));
        }
        if (cache.proves_apart(k, ids, 1, proximity)) {
          ++proved;
          CHECK_FALSE(may);
          continue;
        }
      } else {
        const auto& A = edges[static_cast<size_t>(c.edge_edge[k - n_nf].edge_a)];
        const auto& B = edges[static_cast<size_t>(c.edge_edge[k - n_nf].edge_b)];
        ids = {A[0], A[1], B[0], B[1]};
        auto X0 = [&](int j) { return x0[static_cast<size_t>(ids[static_cast<size_t>(j)])]; };
        auto X1 = [&](int j) { return x1[static_cast<size_t>(ids[static_cast<size_t>(j)])]; };
        may = dcr::edges_may_cross(X0(0), X0(1), X0(2), X0(3), X1(0), X1(1), X1(2), X1(3));
        d = dcr::segment_distance(X0(0), X0(1), X0(2), X0(3));
        slack = dcr::edge_pair_slack(X0(0), X0(1), X0(2), X0(3));
        if (cache.proves_apart_for_any_nodes(k, 0.0)) {
          ++proved_for_any;
          CHECK(cache.proves_apart(k, ids, 2, 0.0));
        }
        if (cache.proves_apart(k, ids, 2, 0.0)) {
          ++proved;
          CHECK_FALSE(may);
          continue;
        }
      }
      if (!may) ++rejected;
      ++recorded;
      cache.record(k, ids, k < n_nf ? 1 : 2, d, slack);
    }
    x0 = x1;
  }
  INFO("proved " << proved << " (" << proved_for_any << " for any nodes), rejected in full "
                 << rejected << ", recorded " << recorded << ", re-anchorings "
                 << cache.reanchorings());
  CHECK(proved > 2 * recorded);      // most pairs decided from their records
  CHECK(proved_for_any > recorded);  // the node-free form decides many of them
  CHECK(cache.reanchorings() > 3);   // the jumps re-anchor
}
