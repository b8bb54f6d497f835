#include "io/fields/element_fields.hpp"

#include <Eigen/LU>
#include <cmath>

#include "engine/element/tet4.hpp"
#include "engine/material/linear_elastic.hpp"
#include "engine/material/neo_hookean.hpp"

namespace ccm::fields {

Mat3 cauchy_stress(MaterialModel model, const Lame& lame, const Mat3& F) {
  if (model == MaterialModel::linear_elastic) return linear_elastic::stress(F, lame);
  const double J = F.determinant();
  const Mat3 cof_F = J * F.inverse().transpose();
  const Mat3 P = neo_hookean::first_piola(F, cof_F, J, lame);
  return P * F.transpose() / J;
}

double von_mises(const Mat3& sigma) {
  const Mat3 s = sigma - sigma.trace() / 3.0 * Mat3::Identity();
  return std::sqrt(1.5 * s.squaredNorm());
}

Mat3 deformation_gradient(const ElementSet& elements, int element, std::span<const Vec3> x) {
  const auto e = static_cast<size_t>(element);
  const Tet& t = elements.tets[e];
  const auto at = [&](int a) -> const Vec3& { return x[static_cast<size_t>(t[a])]; };
  return edge_matrix(at(0), at(1), at(2), at(3)) * elements.reference[e].Dm_inv;
}

std::vector<double> tet_volume_ratio(const ElementSet& elements, std::span<const Vec3> x) {
  std::vector<double> J(elements.tets.size());
  for (int e = 0; e < elements.n_elements(); ++e)
    J[static_cast<size_t>(e)] = deformation_gradient(elements, e, x).determinant();
  return J;
}

std::vector<double> tet_von_mises(const ElementSet& elements, std::span<const Vec3> x) {
  std::vector<double> out(elements.tets.size());
  for (const ElementBlock& block : elements.blocks)
    for (int e = block.first; e < block.first + block.count; ++e)
      out[static_cast<size_t>(e)] =
          von_mises(cauchy_stress(block.model, block.lame, deformation_gradient(elements, e, x)));
  return out;
}

}  // namespace ccm::fields
