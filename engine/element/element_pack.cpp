#include "engine/element/element_pack.hpp"

namespace ccm {

std::vector<ElementPack> make_element_packs(const std::vector<Tet>& tets,
                                            const std::vector<TetReference>& reference, int first,
                                            int count) {
  std::vector<ElementPack> packs(static_cast<size_t>((count + kLanes - 1) / kLanes));
  for (int i = 0; i < static_cast<int>(packs.size()) * kLanes; ++i) {
    ElementPack& p = packs[static_cast<size_t>(i / kLanes)];
    const int l = i % kLanes;
    const bool padding = i >= count;
    const int e = first + (padding ? count - 1 : i);
    const TetReference& ref = reference[static_cast<size_t>(e)];
    for (int k = 0; k < 9; ++k) p.Dm_inv[k][l] = ref.Dm_inv(k / 3, k % 3);
    p.V0[l] = padding ? 0.0 : ref.V0;
    p.inv_6V0[l] = 1.0 / (6.0 * ref.V0);
    for (int a = 0; a < 4; ++a) p.node[a][l] = tets[static_cast<size_t>(e)][static_cast<size_t>(a)];
    p.element[l] = e;
  }
  return packs;
}

}  // namespace ccm
