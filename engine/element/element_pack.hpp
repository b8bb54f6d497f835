// The element data in the layout the SIMD kernel streams through: packs of kLanes elements of
// one material, structure-of-arrays inside a pack ("AoSoA"), so that one lane of every array
// belongs to one element and a loop over lanes vectorizes.
#pragma once

#include <span>
#include <vector>

#include "engine/element/tet4.hpp"
#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

// One SIMD register of doubles: 8 with AVX-512, else 4 (AVX2).
#if defined(__AVX512F__)
#define CCM_LANES_ARE_8 1  // for code that cannot be written for both widths in one form
inline constexpr int kLanes = 8;
#else
#define CCM_LANES_ARE_8 0
inline constexpr int kLanes = 4;
#endif

// The reference geometry a pack carries, per lane: GeometryRows numbers (see the aliases below).
template <int GeometryRows>
struct alignas(64) PackOf {
  static constexpr int kGeometryRows = GeometryRows;
  int node[4][kLanes];
  double V0[kLanes];  // reference volume (a padding lane repeats the last element)
  double geometry[GeometryRows][kLanes];
};

// Neo-Hookean: G = Dm^-1 Dm^-T (symmetric; entries 00 11 22 01 02 12). The forces need no F:
// H = -V0 P Dm^-T = -mu V0 Ds G + V0 (mu - lambda ln J) Ds^-T (docs/equations.md).
using NeoHookeanPack = PackOf<6>;
// Linear elastic: Dm^-1, row-major (the small strain needs F = Ds Dm^-1 itself).
using LinearPack = PackOf<9>;

// Packs the given elements in order; the last pack is padded by repeating the last element
// (its padding lanes are skipped by the scatter and the sums).
template <class Pack>
std::vector<Pack> make_element_packs(const std::vector<Tet>& tets,
                                     const std::vector<TetReference>& reference,
                                     std::span<const int> elements);

}  // namespace ccm
