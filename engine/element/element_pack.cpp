#include "engine/element/element_pack.hpp"

namespace ccm {
namespace {

void fill_geometry(NeoHookeanPack& p, int l, const Mat3& Dm_inv) {
  const Mat3 G = Dm_inv * Dm_inv.transpose();
  constexpr int kRow[6] = {0, 1, 2, 0, 0, 1}, kCol[6] = {0, 1, 2, 1, 2, 2};
  for (int k = 0; k < 6; ++k) p.geometry[k][l] = G(kRow[k], kCol[k]);
}

void fill_geometry(LinearPack& p, int l, const Mat3& Dm_inv) {
  for (int k = 0; k < 9; ++k) p.geometry[k][l] = Dm_inv(k / 3, k % 3);
}

}  // namespace

template <class Pack>
std::vector<Pack> make_element_packs(const std::vector<Tet>& tets,
                                     const std::vector<TetReference>& reference,
                                     std::span<const int> elements) {
  const int count = static_cast<int>(elements.size());
  std::vector<Pack> packs(static_cast<size_t>((count + kLanes - 1) / kLanes));
  for (int i = 0; i < static_cast<int>(packs.size()) * kLanes; ++i) {
    Pack& p = packs[static_cast<size_t>(i / kLanes)];
    const int l = i % kLanes;
    const auto e = static_cast<size_t>(elements[static_cast<size_t>(std::min(i, count - 1))]);
    fill_geometry(p, l, reference[e].Dm_inv);
    p.V0[l] = reference[e].V0;
    for (int a = 0; a < 4; ++a) p.node[a][l] = tets[e][static_cast<size_t>(a)];
  }
  return packs;
}

template std::vector<NeoHookeanPack> make_element_packs(const std::vector<Tet>&,
                                                        const std::vector<TetReference>&,
                                                        std::span<const int>);
template std::vector<LinearPack> make_element_packs(const std::vector<Tet>&,
                                                    const std::vector<TetReference>&,
                                                    std::span<const int>);

}  // namespace ccm
