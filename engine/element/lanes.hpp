// A vector of kLanes doubles (GCC vector extension: one SIMD register), the log the Neo-Hookean
// kernel needs on it, and the moves between lanes and nodal arrays of padded nodes
// (padded_nodes.hpp): a pack's node slot is one aligned 256-bit load per lane and a transpose by
// shuffles, and its forces go back by the reverse transpose and one 256-bit read-add-write per
// lane. (On nodes packed as three doubles, masked 256-bit
// moves were measured slower than scalar ones: masked stores do not forward to the next read of
// the same node.)
#pragma once

#include <cmath>
#include <cstring>

#include "engine/element/element_pack.hpp"
#include "engine/element/padded_nodes.hpp"

namespace ccm {

using Lanes = double __attribute__((vector_size(kLanes * sizeof(double))));

// glibc's libmvec vector log (AVX-512 or AVX2 variant, < 4 ulp). math.h declares it only under
// -ffast-math, which would also drop the NaN semantics the stability monitor relies on, so it
// is declared here under its ABI name. Results repeat exactly on the same machine.
#if defined(__x86_64__) && defined(__AVX512F__) && defined(__GLIBC__)
extern "C" Lanes _ZGVeN8v_log(Lanes) noexcept;  // the AVX-512 variant (8 lanes)
inline Lanes vector_log(Lanes v) { return _ZGVeN8v_log(v); }
#elif defined(__x86_64__) && defined(__AVX2__) && defined(__GLIBC__)
extern "C" Lanes _ZGVdN4v_log(Lanes) noexcept;
inline Lanes vector_log(Lanes v) { return _ZGVdN4v_log(v); }
#else
inline Lanes vector_log(Lanes v) {
  for (int l = 0; l < kLanes; ++l) v[l] = std::log(v[l]);
  return v;
}
#endif

// ln J of the lanes, for the kernels' ln J: the series of ln(1 + x), x = J - 1 (exact for J in
// [0.5, 2]), when every lane lies within 1/64 of 1, else vector_log. A small-strain body (the
// rig's PVC, |J - 1| < 1e-2) spends a sixth of its step in vector_log; the series is ten fused
// multiply-adds. Truncated after x^10 its relative error is below |x|^10 / 11 < 2^-63 (under
// 1/1000 ulp), so the result is within rounding of ln J (test_lanes.cpp: <= 1 ulp of std::log).
//   ln(1 + x) = x + x^2 sum_{k>=2} (-1)^(k+1) x^(k-2) / k,  |x| < 1
inline constexpr double kSeriesLogRange = 1.0 / 64.0;

inline bool all_lanes_near_one(Lanes v) {
  const Lanes x = v - 1.0;
  bool all = true;
  for (int l = 0; l < kLanes; ++l) all &= x[l] < kSeriesLogRange && x[l] > -kSeriesLogRange;
  return all;
}

inline Lanes series_log_near_one(Lanes v) {
  const Lanes x = v - 1.0;
  Lanes q = Lanes{} + 1.0 / 10.0;
  q = q * x - 1.0 / 9.0;
  q = q * x + 1.0 / 8.0;
  q = q * x - 1.0 / 7.0;
  q = q * x + 1.0 / 6.0;
  q = q * x - 1.0 / 5.0;
  q = q * x + 1.0 / 4.0;
  q = q * x - 1.0 / 3.0;
  q = q * x + 1.0 / 2.0;
  return x - x * x * q;
}

inline Lanes kernel_log(Lanes v) {
  return all_lanes_near_one(v) ? series_log_near_one(v) : vector_log(v);
}

// One padded node as a vector (x, y, z, 0).
using Quad = double __attribute__((vector_size(4 * sizeof(double))));

inline Quad load_quad(const PaddedVec3& a) {
  Quad q;
  std::memcpy(&q, a.v, sizeof q);
  return q;
}

// x[l], y[l], z[l], w[l]: the four components of the padded nodes n_l of the lanes (w is 0 for
// positions; a kernel may keep a nodal value there). One aligned 256-bit load per node, then a
// transpose by shuffles: [x y z w] rows to x, y, z and w lanes.
#define CCM_LANES_INLINE inline __attribute__((always_inline))
CCM_LANES_INLINE void gather_xyzw(const PaddedVec3* a, const int (&n)[kLanes], Lanes& x, Lanes& y,
                                  Lanes& z, Lanes& w) {
#define CCM_ROW(l) load_quad(a[n[l]])
#if CCM_LANES_ARE_8
  // t_k = [node k | node k + 4]; unpacks give x z and y w pairs; a two-source permute finishes.
  const Lanes t0 = __builtin_shufflevector(CCM_ROW(0), CCM_ROW(4), 0, 1, 2, 3, 4, 5, 6, 7);
  const Lanes t1 = __builtin_shufflevector(CCM_ROW(1), CCM_ROW(5), 0, 1, 2, 3, 4, 5, 6, 7);
  const Lanes t2 = __builtin_shufflevector(CCM_ROW(2), CCM_ROW(6), 0, 1, 2, 3, 4, 5, 6, 7);
  const Lanes t3 = __builtin_shufflevector(CCM_ROW(3), CCM_ROW(7), 0, 1, 2, 3, 4, 5, 6, 7);
  const Lanes xz01 = __builtin_shufflevector(t0, t1, 0, 8, 2, 10, 4, 12, 6, 14);
  const Lanes yw01 = __builtin_shufflevector(t0, t1, 1, 9, 3, 11, 5, 13, 7, 15);
  const Lanes xz23 = __builtin_shufflevector(t2, t3, 0, 8, 2, 10, 4, 12, 6, 14);
  const Lanes yw23 = __builtin_shufflevector(t2, t3, 1, 9, 3, 11, 5, 13, 7, 15);
  x = __builtin_shufflevector(xz01, xz23, 0, 1, 8, 9, 4, 5, 12, 13);
  y = __builtin_shufflevector(yw01, yw23, 0, 1, 8, 9, 4, 5, 12, 13);
  z = __builtin_shufflevector(xz01, xz23, 2, 3, 10, 11, 6, 7, 14, 15);
  w = __builtin_shufflevector(yw01, yw23, 2, 3, 10, 11, 6, 7, 14, 15);
#else
  const Quad r0 = CCM_ROW(0), r1 = CCM_ROW(1), r2 = CCM_ROW(2), r3 = CCM_ROW(3);
  const Lanes xz01 = __builtin_shufflevector(r0, r1, 0, 4, 2, 6);
  const Lanes yw01 = __builtin_shufflevector(r0, r1, 1, 5, 3, 7);
  const Lanes xz23 = __builtin_shufflevector(r2, r3, 0, 4, 2, 6);
  const Lanes yw23 = __builtin_shufflevector(r2, r3, 1, 5, 3, 7);
  x = __builtin_shufflevector(xz01, xz23, 0, 1, 4, 5);
  y = __builtin_shufflevector(yw01, yw23, 0, 1, 4, 5);
  z = __builtin_shufflevector(xz01, xz23, 2, 3, 6, 7);
  w = __builtin_shufflevector(yw01, yw23, 2, 3, 6, 7);
#endif
#undef CCM_ROW
}

// x[l], y[l], z[l]: the coordinates of the nodes n_l (the unused w shuffle is dropped by the
// compiler).
CCM_LANES_INLINE void gather_xyz(const PaddedVec3* a, const int (&n)[kLanes], Lanes& x, Lanes& y,
                                 Lanes& z) {
  Lanes w;
  gather_xyzw(a, n, x, y, z, w);
}

// The forces (x, y, z)[l] of the lanes as one padded row per lane, (x, y, z, 0)[l]: the
// reverse transpose.
struct LaneRows {
#if CCM_LANES_ARE_8
  Lanes pair[4];  // pair[k] = [row k | row k + 4]
  Quad row(int l) const {
    return l < 4 ? __builtin_shufflevector(pair[l], pair[l], 0, 1, 2, 3)
                 : __builtin_shufflevector(pair[l - 4], pair[l - 4], 4, 5, 6, 7);
  }
#else
  Lanes rows[4];
  Quad row(int l) const { return rows[l]; }
#endif
};

inline LaneRows lane_rows(Lanes x, Lanes y, Lanes z) {
  const Lanes zero{};
  LaneRows r;
#if CCM_LANES_ARE_8
  const Lanes xz01 = __builtin_shufflevector(x, z, 0, 1, 8, 9, 4, 5, 12, 13);
  const Lanes xz23 = __builtin_shufflevector(x, z, 2, 3, 10, 11, 6, 7, 14, 15);
  const Lanes y01 = __builtin_shufflevector(y, zero, 0, 1, 8, 9, 4, 5, 12, 13);
  const Lanes y23 = __builtin_shufflevector(y, zero, 2, 3, 10, 11, 6, 7, 14, 15);
  r.pair[0] = __builtin_shufflevector(xz01, y01, 0, 8, 2, 10, 4, 12, 6, 14);
  r.pair[1] = __builtin_shufflevector(xz01, y01, 1, 9, 3, 11, 5, 13, 7, 15);
  r.pair[2] = __builtin_shufflevector(xz23, y23, 0, 8, 2, 10, 4, 12, 6, 14);
  r.pair[3] = __builtin_shufflevector(xz23, y23, 1, 9, 3, 11, 5, 13, 7, 15);
#else
  const Lanes xz01 = __builtin_shufflevector(x, z, 0, 4, 1, 5);  // x0 z0 x1 z1
  const Lanes xz23 = __builtin_shufflevector(x, z, 2, 6, 3, 7);
  const Lanes y01 = __builtin_shufflevector(y, zero, 0, 4, 1, 5);  // y0 0 y1 0
  const Lanes y23 = __builtin_shufflevector(y, zero, 2, 6, 3, 7);
  r.rows[0] = __builtin_shufflevector(xz01, y01, 0, 4, 1, 5);  // x0 y0 z0 0
  r.rows[1] = __builtin_shufflevector(xz01, y01, 2, 6, 3, 7);
  r.rows[2] = __builtin_shufflevector(xz23, y23, 0, 4, 1, 5);
  r.rows[3] = __builtin_shufflevector(xz23, y23, 2, 6, 3, 7);
#endif
  return r;
}

// a += row l of r: each of the three components added once, as scalar adds would (the fourth
// adds 0 to 0).
inline void add_row(const LaneRows& r, int l, PaddedVec3& a) {
  const Quad sum = load_quad(a) + r.row(l);
  std::memcpy(a.v, &sum, sizeof sum);
}

// Adds the first `lanes` lanes' nodal forces of a pack into f: h[a][i] is component i of the
// force on local node a + 1, node 0 takes minus their sum. Lane by lane, nodes 1, 2, 3 then 0:
// the fixed order every thread count shares (lanes may share nodes).
CCM_LANES_INLINE void scatter_forces(const int (&node)[4][kLanes], const Lanes (&h)[3][3],
                                     int lanes, PaddedVec3* f) {
  const LaneRows rows[4] = {
      lane_rows(-(h[0][0] + h[1][0] + h[2][0]), -(h[0][1] + h[1][1] + h[2][1]),
                -(h[0][2] + h[1][2] + h[2][2])),
      lane_rows(h[0][0], h[0][1], h[0][2]), lane_rows(h[1][0], h[1][1], h[1][2]),
      lane_rows(h[2][0], h[2][1], h[2][2])};
  for (int l = 0; l < lanes; ++l) {
    for (int a = 1; a < 4; ++a) add_row(rows[a], l, f[node[a][l]]);
    add_row(rows[0], l, f[node[0][l]]);
  }
}

}  // namespace ccm
