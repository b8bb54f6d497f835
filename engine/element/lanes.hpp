// A vector of kLanes doubles (GCC vector extension: one SIMD register), the log the Neo-Hookean
// kernel needs on it, and the gather of a nodal array of Vec3 (x y z, packed) into lanes.
// (Gathers and scatters by masked 256-bit loads and stores and an 8 x 4 transpose were measured
// slower here than these scalar moves: the scatter's masked stores do not forward to the next
// read of the same node.)
#pragma once

#include <cmath>

#include "engine/element/element_pack.hpp"

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

// x[l] = a[3 n_l], y[l] = a[3 n_l + 1], z[l] = a[3 n_l + 2] for the nodes n_l of the lanes.
inline void gather_xyz(const double* a, const int (&n)[kLanes], Lanes& x, Lanes& y, Lanes& z) {
  Lanes gx{}, gy{}, gz{};
  for (int l = 0; l < kLanes; ++l) {
    gx[l] = a[3 * n[l]];
    gy[l] = a[3 * n[l] + 1];
    gz[l] = a[3 * n[l] + 2];
  }
  x = gx;
  y = gy;
  z = gz;
}

}  // namespace ccm
