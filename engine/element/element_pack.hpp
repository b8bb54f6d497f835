// The element data in the layout the SIMD kernel streams through: packs of kLanes elements of
// one material, structure-of-arrays inside a pack ("AoSoA"), so that one lane of every array
// belongs to one element and a loop over lanes vectorizes.
#pragma once

#include <vector>

#include "engine/element/tet4.hpp"
#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

// One AVX2 register of doubles. (8 lanes in AVX-512 registers measured 1.6x slower here.)
inline constexpr int kLanes = 4;

struct alignas(64) ElementPack {
  double Dm_inv[9][kLanes];  // row-major entries of Dm^-1
  double V0[kLanes];         // reference volume; 0 in padding lanes (they add no force)
  double inv_6V0[kLanes];    // 1 / (6 V0), so J = det(Ds) / (6 V0)
  int node[4][kLanes];
  int element[kLanes];  // global element index (padding lanes repeat the last element)
};

// Packs elements [first, first + count); the last pack is padded by repeating the last element
// with zero volume weight.
std::vector<ElementPack> make_element_packs(const std::vector<Tet>& tets,
                                            const std::vector<TetReference>& reference, int first,
                                            int count);

}  // namespace ccm
