#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "engine/contact/dcr/ccd.hpp"
#include "tests/support/tolerance.hpp"

using ccm::Vec3;
using ccm::dcr::edge_edge_ccd;
using ccm::dcr::edge_edge_volume;
using ccm::dcr::edge_edge_volume_gradient;
using ccm::dcr::node_face_ccd;
using ccm::dcr::node_face_volume;
using ccm::dcr::node_face_volume_gradient;
using ccm::test::relative_error;

namespace {

using Volume = double (*)(const Vec3&, const Vec3&, const Vec3&, const Vec3&);
using Gradient = void (*)(const Vec3&, const Vec3&, const Vec3&, const Vec3&, Vec3[4]);

Vec3 random_point(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return {u(rng), u(rng), u(rng)};
}

// Checks a volume's gradient against central differences and its rigid-motion invariances.
void check_gradient(Volume g, Gradient grad, std::mt19937& rng) {
  std::array<Vec3, 4> x = {random_point(rng), random_point(rng), random_point(rng),
                           random_point(rng)};
  Vec3 gr[4];
  grad(x[0], x[1], x[2], x[3], gr);

  const double h = 1e-6;
  for (size_t a = 0; a < 4; ++a) {
    Vec3 fd;
    for (int d = 0; d < 3; ++d) {
      std::array<Vec3, 4> xp = x, xm = x;
      xp[a][d] += h;
      xm[a][d] -= h;
      fd[d] = (g(xp[0], xp[1], xp[2], xp[3]) - g(xm[0], xm[1], xm[2], xm[3])) / (2 * h);
    }
    CHECK(relative_error(gr[a], fd, 1e-3) < 1e-7);
  }
  Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
  double scale = 0;
  for (size_t a = 0; a < 4; ++a) {
    force += gr[a];
    torque += x[a].cross(gr[a]);
    scale = std::max(scale, gr[a].norm());
  }
  CHECK(force.norm() <= 1e-14 * scale);   // linear momentum
  CHECK(torque.norm() <= 1e-14 * scale);  // angular momentum

  // Invariant under a rigid motion.
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 shift(0.3, -2.0, 5.0);
  const double g0 = g(x[0], x[1], x[2], x[3]);
  const double g1 =
      g(rot * x[0] + shift, rot * x[1] + shift, rot * x[2] + shift, rot * x[3] + shift);
  CHECK(std::abs(g1 - g0) <= 1e-13);
}

// Positions of a point moving linearly.
Vec3 lerp(const Vec3& x0, const Vec3& x1, double t) { return (1 - t) * x0 + t * x1; }

}  // namespace

TEST_CASE("DCR volumes: values, gradients against finite differences, invariances", "[dcr]") {
  // node-face: g = (A/3) d for a node at height d above a face of area A.
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 3, 0);
  CHECK(node_face_volume(Vec3(0.5, 0.5, 0.4), a, b, c) == Approx(3.0 / 3.0 * 0.4));
  CHECK(node_face_volume(Vec3(0.5, 0.5, -0.4), a, b, c) == Approx(-0.4));
  // edge-edge: unit crossed edges a unit apart.
  CHECK(edge_edge_volume(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 1)) ==
        Approx(1.0 / 6.0));

  // At contact the gradient is (A/3)[n, -w_a n, -w_b n, -w_c n] (docs/contact-method.md §1.1).
  Vec3 gr[4];
  node_face_volume_gradient(Vec3(0.5, 0.75, 0), a, b, c, gr);
  const double w_b = 0.25, w_c = 0.25, w_a = 0.5;
  CHECK(relative_error(gr[0], Vec3(0, 0, 1.0)) < 1e-14);
  CHECK(relative_error(gr[1], Vec3(0, 0, -w_a)) < 1e-14);
  CHECK(relative_error(gr[2], Vec3(0, 0, -w_b)) < 1e-14);
  CHECK(relative_error(gr[3], Vec3(0, 0, -w_c)) < 1e-14);

  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    check_gradient(node_face_volume, node_face_volume_gradient, rng);
    check_gradient(edge_edge_volume, edge_edge_volume_gradient, rng);
  }
}

TEST_CASE("node-face CCD: a node passing through a face", "[dcr][ccd]") {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);

  SECTION("fixed face: the time of impact is exact") {
    const auto hit = node_face_ccd(Vec3(0.2, 0.3, 0.7), a, b, c, Vec3(0.2, 0.3, -0.3), a, b, c, 0);
    REQUIRE(hit);
    CHECK(hit->toi == Approx(0.7).epsilon(1e-14));
    CHECK(hit->w_a == Approx(0.5).epsilon(1e-14));
    CHECK(hit->w_b == Approx(0.2).epsilon(1e-14));
    CHECK(hit->w_c == Approx(0.3).epsilon(1e-14));
  }
  SECTION("everything moving, linear relative motion: the time is still exact") {
    const Vec3 drift(0.5, -0.2, 0.4);
    const Vec3 far(1e3, -2e3, 5e2);  // far from the origin: no digits lost
    const auto hit = node_face_ccd(Vec3(0.2, 0.3, 0.7) + far, a + far, b + far, c + far,
                                   Vec3(0.2, 0.3, -0.3) + far + drift, a + far + drift,
                                   b + far + drift, c + far + drift, 0);
    REQUIRE(hit);
    CHECK(hit->toi == Approx(0.7).epsilon(1e-12));
    CHECK(hit->w_b == Approx(0.2).epsilon(1e-10));
    CHECK(hit->w_c == Approx(0.3).epsilon(1e-10));
  }
  SECTION("coming from below is a root as well") {
    const auto hit =
        node_face_ccd(Vec3(0.2, 0.3, -0.25), a, b, c, Vec3(0.2, 0.3, 0.75), a, b, c, 0);
    REQUIRE(hit);
    CHECK(hit->toi == Approx(0.25).epsilon(1e-14));
  }
  SECTION("passing beside the face is no hit") {
    CHECK_FALSE(node_face_ccd(Vec3(0.7, 0.7, 0.5), a, b, c, Vec3(0.7, 0.7, -0.5), a, b, c, 1e-6));
    CHECK_FALSE(node_face_ccd(Vec3(-0.1, 0.5, 0.5), a, b, c, Vec3(-0.1, 0.5, -0.5), a, b, c, 0));
    // ... unless the tolerance reaches it.
    CHECK(node_face_ccd(Vec3(-0.1, 0.5, 0.5), a, b, c, Vec3(-0.1, 0.5, -0.5), a, b, c, 0.2));
  }
  SECTION("through a triangle edge or vertex exactly, with a tiny tolerance") {
    const auto edge = node_face_ccd(Vec3(0.5, 0, 1), a, b, c, Vec3(0.5, 0, -1), a, b, c, 1e-12);
    REQUIRE(edge);
    CHECK(edge->toi == Approx(0.5));
    CHECK(std::abs(edge->w_c) < 1e-12);
    const auto vertex = node_face_ccd(Vec3(1, 0, 1), a, b, c, Vec3(1, 0, -1), a, b, c, 1e-12);
    REQUIRE(vertex);
    CHECK(vertex->w_b == Approx(1.0));
  }
  SECTION("not reaching the face during the step is no hit") {
    CHECK_FALSE(node_face_ccd(Vec3(0.2, 0.3, 0.7), a, b, c, Vec3(0.2, 0.3, 0.1), a, b, c, 0));
  }
}

TEST_CASE("node-face CCD: motion parallel to the face plane", "[dcr][ccd]") {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  SECTION("above the plane: never touches") {
    CHECK_FALSE(node_face_ccd(Vec3(-1, 0.25, 0.1), a, b, c, Vec3(1, 0.25, 0.1), a, b, c, 1e-6));
  }
  SECTION("a hair above the plane, crossing over the face: no hit") {
    CHECK_FALSE(node_face_ccd(Vec3(-1, 0.25, 1e-9), a, b, c, Vec3(1, 0.25, 1e-9), a, b, c, 1e-6));
  }
  SECTION("in the plane: a hit from the moment the node enters the triangle") {
    const auto hit = node_face_ccd(Vec3(-1, 0.25, 0), a, b, c, Vec3(1, 0.25, 0), a, b, c, 0);
    REQUIRE(hit);
    CHECK(hit->toi == Approx(0.5).margin(1e-9));
    CHECK(hit->w_b == Approx(0).margin(1e-9));
    CHECK(hit->w_c == Approx(0.25).margin(1e-9));
  }
  SECTION("in the plane but beside the triangle: no hit") {
    CHECK_FALSE(node_face_ccd(Vec3(-1, 1.5, 0), a, b, c, Vec3(1, 1.5, 0), a, b, c, 1e-6));
  }
  SECTION("in the plane of a tilted, moving face") {
    // The face and the node share one rigid motion plus an in-plane slide of the node.
    const Eigen::Matrix3d rot = Eigen::AngleAxisd(0.4, Vec3(1, -1, 2).normalized()).matrix();
    const Vec3 shift(0.1, 0.2, -0.3);
    auto place = [&](const Vec3& v) -> Vec3 { return rot * v + shift; };
    const auto hit = node_face_ccd(place(Vec3(-1, 0.25, 0)), place(a), place(b), place(c),
                                   place(Vec3(1, 0.25, 0)), place(a), place(b), place(c), 1e-9);
    REQUIRE(hit);
    CHECK(hit->toi == Approx(0.5).margin(1e-8));
  }
}

TEST_CASE("node-face CCD: starting on the face plane", "[dcr][ccd]") {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  SECTION("inside the triangle, moving in: a hit at toi = 0") {
    const auto hit = node_face_ccd(Vec3(0.2, 0.2, 0), a, b, c, Vec3(0.2, 0.2, -0.1), a, b, c, 0);
    REQUIRE(hit);
    CHECK(hit->toi == 0);
    CHECK(hit->w_a == Approx(0.6));
  }
  SECTION("inside the triangle, moving out: still reported as touching at toi = 0") {
    const auto hit = node_face_ccd(Vec3(0.2, 0.2, 0), a, b, c, Vec3(0.2, 0.2, 0.1), a, b, c, 0);
    REQUIRE(hit);
    CHECK(hit->toi == 0);
  }
  SECTION("outside the triangle: no hit") {
    CHECK_FALSE(node_face_ccd(Vec3(0.8, 0.8, 0), a, b, c, Vec3(0.8, 0.8, -0.1), a, b, c, 1e-6));
  }
  SECTION("ending exactly on the face: a hit at toi = 1") {
    const auto hit = node_face_ccd(Vec3(0.2, 0.2, 0.5), a, b, c, Vec3(0.2, 0.2, 0), a, b, c, 0);
    REQUIRE(hit);
    CHECK(hit->toi == 1);
  }
}

TEST_CASE("node-face CCD: the first root is outside the triangle, the second inside",
          "[dcr][ccd]") {
  // a, b fixed; c tilts down; 6 g(tau) = 0.2 (tau - 0.25)(tau - 0.75). At tau = 0.25 the node
  // is beyond edge bc (w_a = -0.25), at 0.75 inside with w = (0.15, 0.5, 0.35).
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  const Vec3 c0(0, 1, 0), c1(0, 1, -1);
  const Vec3 p0(1.25, 0.2, 0.0375), p1(0.25, 0.4, -0.3625);
  for (double t : {0.25, 0.75})
    CHECK(std::abs(node_face_volume(lerp(p0, p1, t), a, b, lerp(c0, c1, t))) < 1e-15);

  const auto hit = node_face_ccd(p0, a, b, c0, p1, a, b, c1, 1e-9);
  REQUIRE(hit);
  CHECK(hit->toi == Approx(0.75).epsilon(1e-13));
  CHECK(hit->w_a == Approx(0.15).epsilon(1e-12));
  CHECK(hit->w_b == Approx(0.5).epsilon(1e-12));
  CHECK(hit->w_c == Approx(0.35).epsilon(1e-12));

  // A wide tolerance catches the first root.
  const auto early = node_face_ccd(p0, a, b, c0, p1, a, b, c1, 0.3);
  REQUIRE(early);
  CHECK(early->toi == Approx(0.25).epsilon(1e-13));
}

TEST_CASE("edge-edge CCD", "[dcr][ccd]") {
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  SECTION("crossing edges: exact time and parameters") {
    const Vec3 c0(0.3, -0.5, 0.4), d0(0.3, 0.5, 0.4), down(0, 0, -1);
    const auto hit = edge_edge_ccd(a, b, c0, d0, a, b, c0 + down, d0 + down, 0);
    REQUIRE(hit);
    CHECK(hit->toi == Approx(0.4).epsilon(1e-14));
    CHECK(hit->s == Approx(0.3).epsilon(1e-14));
    CHECK(hit->t == Approx(0.5).epsilon(1e-14));
  }
  SECTION("both edges moving and rotating") {
    // Edge ab rises and turns about z; cd descends. Check the reported crossing directly.
    const Vec3 a1(0, 0, 0.2), b1(0.8, 0.6, 0.2);
    const Vec3 c0(0.5, -0.5, 0.6), d0(0.5, 0.7, 0.6), c1(0.4, -0.4, -0.3), d1(0.4, 0.8, -0.3);
    const auto hit = edge_edge_ccd(a, b, c0, d0, a1, b1, c1, d1, 0);
    REQUIRE(hit);
    const double t = hit->toi;
    const Vec3 on_a = (1 - hit->s) * lerp(a, a1, t) + hit->s * lerp(b, b1, t);
    const Vec3 on_b = (1 - hit->t) * lerp(c0, c1, t) + hit->t * lerp(d0, d1, t);
    CHECK((on_a - on_b).norm() < 1e-12);
    CHECK(hit->s >= 0);
    CHECK(hit->s <= 1);
    CHECK(hit->t >= 0);
    CHECK(hit->t <= 1);
  }
  SECTION("passing beyond the end of an edge: no hit") {
    const Vec3 c0(1.3, -0.5, 0.4), d0(1.3, 0.5, 0.4), down(0, 0, -1);
    CHECK_FALSE(edge_edge_ccd(a, b, c0, d0, a, b, c0 + down, d0 + down, 1e-6));
  }
  SECTION("near-parallel edges crossing") {
    const double delta = 1e-4;
    const Vec3 c0(0.2, -delta, 0.5), d0(0.8, delta, 0.5), down(0, 0, -1);
    const auto hit = edge_edge_ccd(a, b, c0, d0, a, b, c0 + down, d0 + down, 0);
    REQUIRE(hit);
    CHECK(hit->toi == Approx(0.5).epsilon(1e-14));
    CHECK(hit->s == Approx(0.5).epsilon(1e-10));
    CHECK(hit->t == Approx(0.5).epsilon(1e-10));
  }
  SECTION("near-parallel edges whose lines cross beyond the edges: no hit") {
    const double delta = 1e-4;
    const Vec3 c0(1.2, -delta, 0.5), d0(1.8, delta, 0.5), down(0, 0, -1);
    CHECK_FALSE(edge_edge_ccd(a, b, c0, d0, a, b, c0 + down, d0 + down, 1e-6));
  }
  SECTION("exactly parallel edges are left to the node-face pairs") {
    const Vec3 c0(0.2, 0, 0.5), d0(0.8, 0, 0.5), down(0, 0, -1);
    CHECK_FALSE(edge_edge_ccd(a, b, c0, d0, a, b, c0 + down, d0 + down, 1e-6));
  }
  SECTION("coplanar edges sliding into each other") {
    const Vec3 c0(0.5, 0.2, 0), d0(0.5, 1.2, 0), shift(0, -1, 0);
    const auto hit = edge_edge_ccd(a, b, c0, d0, a, b, c0 + shift, d0 + shift, 0);
    REQUIRE(hit);
    CHECK(hit->toi == Approx(0.2).margin(1e-9));
    CHECK(hit->s == Approx(0.5).margin(1e-9));
    CHECK(hit->t == Approx(0).margin(1e-9));
  }
}

TEST_CASE("node-face CCD agrees with a dense sampling on random motions", "[dcr][ccd]") {
  // Every hit must be a real touching of the triangle; every crossing that dense sampling sees
  // clearly inside the triangle must be found, no later than it.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int n_hits = 0, n_sampled = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const Vec3 a0(0, 0, 0), b0(1, 0, 0), c0(0, 1, 0);
    auto jitter = [&](const Vec3& v, double s) -> Vec3 {
      return v + s * Vec3(u(rng), u(rng), u(rng));
    };
    const Vec3 a1 = jitter(a0, 0.4), b1 = jitter(b0, 0.4), c1 = jitter(c0, 0.4);
    const Vec3 p0(0.5 * u(rng) + 0.3, 0.5 * u(rng) + 0.3, 0.5 * u(rng));
    const Vec3 p1 = jitter(p0, 1.0);
    const auto hit = node_face_ccd(p0, a0, b0, c0, p1, a1, b1, c1, 0);

    auto g = [&](double t) {
      return node_face_volume(lerp(p0, p1, t), lerp(a0, a1, t), lerp(b0, b1, t), lerp(c0, c1, t));
    };
    if (hit) {
      ++n_hits;
      const double t = hit->toi;
      const Vec3 a = lerp(a0, a1, t), b = lerp(b0, b1, t), c = lerp(c0, c1, t);
      const Vec3 p = lerp(p0, p1, t);
      CHECK(std::abs(g(t)) < 1e-12);
      CHECK((hit->w_a * a + hit->w_b * b + hit->w_c * c - p).norm() < 1e-9);
      CHECK(std::min({hit->w_a, hit->w_b, hit->w_c}) > -1e-9);
    }
    // Dense sampling: the first sign change whose crossing lies clearly inside.
    const int n = 1000;
    double prev = g(0);
    for (int k = 1; k <= n; ++k) {
      const double t1 = static_cast<double>(k) / n;
      const double cur = g(t1);
      if ((prev < 0) != (cur < 0)) {
        const double t0 = static_cast<double>(k - 1) / n;
        const double tc = t0 + (t1 - t0) * prev / (prev - cur);
        const Vec3 a = lerp(a0, a1, tc), b = lerp(b0, b1, tc), c = lerp(c0, c1, tc);
        const Vec3 p = lerp(p0, p1, tc);
        const Vec3 nrm = (b - a).cross(c - a);
        const double wb = (p - a).cross(c - a).dot(nrm) / nrm.squaredNorm();
        const double wc = (b - a).cross(p - a).dot(nrm) / nrm.squaredNorm();
        if (std::min({wb, wc, 1 - wb - wc}) > 1e-3) {
          ++n_sampled;
          REQUIRE(hit);
          CHECK(hit->toi <= t1);
          break;
        }
      }
      prev = cur;
    }
  }
  INFO("hits " << n_hits << ", crossings found by sampling " << n_sampled);
  CHECK(n_hits > 40);
  CHECK(n_sampled > 40);
}

TEST_CASE("edge-edge CCD agrees with a dense sampling on random motions", "[dcr][ccd]") {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int n_hits = 0, n_sampled = 0;
  for (int trial = 0; trial < 600; ++trial) {
    auto rnd = [&](double s) -> Vec3 { return s * Vec3(u(rng), u(rng), u(rng)); };
    const Vec3 a0 = rnd(0.5), b0 = Vec3(1, 0, 0) + rnd(0.5), c0 = Vec3(0.5, -0.5, 0.3) + rnd(0.5),
               d0 = Vec3(0.5, 0.5, 0.3) + rnd(0.5);
    const Vec3 a1 = a0 + rnd(0.5), b1 = b0 + rnd(0.5), c1 = c0 + rnd(0.8), d1 = d0 + rnd(0.8);
    const auto hit = edge_edge_ccd(a0, b0, c0, d0, a1, b1, c1, d1, 0);
    auto g = [&](double t) {
      return edge_edge_volume(lerp(a0, a1, t), lerp(b0, b1, t), lerp(c0, c1, t), lerp(d0, d1, t));
    };
    if (hit) {
      ++n_hits;
      const double t = hit->toi;
      const Vec3 on_a = (1 - hit->s) * lerp(a0, a1, t) + hit->s * lerp(b0, b1, t);
      const Vec3 on_b = (1 - hit->t) * lerp(c0, c1, t) + hit->t * lerp(d0, d1, t);
      CHECK(std::abs(g(t)) < 1e-12);
      CHECK((on_a - on_b).norm() < 1e-9);
    }
    const int n = 1000;
    double prev = g(0);
    for (int k = 1; k <= n; ++k) {
      const double t1 = static_cast<double>(k) / n;
      const double cur = g(t1);
      if ((prev < 0) != (cur < 0)) {
        const double t0 = static_cast<double>(k - 1) / n;
        const double tc = t0 + (t1 - t0) * prev / (prev - cur);
        const Vec3 e1 = lerp(b0, b1, tc) - lerp(a0, a1, tc);
        const Vec3 e2 = lerp(d0, d1, tc) - lerp(c0, c1, tc);
        const Vec3 r = lerp(c0, c1, tc) - lerp(a0, a1, tc);
        const Vec3 nrm = e1.cross(e2);
        const double s = r.cross(e2).dot(nrm) / nrm.squaredNorm();
        const double tt = r.cross(e1).dot(nrm) / nrm.squaredNorm();
        if (std::min({s, tt, 1 - s, 1 - tt}) > 1e-3) {
          ++n_sampled;
          REQUIRE(hit);
          CHECK(hit->toi <= t1);
          break;
        }
      }
      prev = cur;
    }
  }
  INFO("hits " << n_hits << ", crossings found by sampling " << n_sampled);
  CHECK(n_hits > 40);
  CHECK(n_sampled > 40);
}
