// Per-tet fields of the current configuration: the volume ratio J = det F and the von Mises
// equivalent of the Cauchy stress, from the material laws of engine/material (docs/fields.md).
#pragma once

#include <span>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/element/internal_force.hpp"
#include "engine/material/material.hpp"

namespace ccm::fields {

// Cauchy stress sigma = P F^T / J of the body's law (docs/equations.md "Material"):
//   neo_hookean: P of engine/material/neo_hookean.hpp (thesis eq. 2.3), which is
//                sigma = mu/J (F F^T - I) + lambda ln(J)/J I;
//   linear_elastic: sigma of eq. 2.1 (the engine takes P = sigma there).
Mat3 cauchy_stress(MaterialModel model, const Lame& lame, const Mat3& F);

// sqrt(3/2 s:s), s = sigma - tr(sigma)/3 I, the deviatoric part.
double von_mises(const Mat3& sigma);

// F = Ds Dm^-1 of each tet of `elements` at positions x (tet4.hpp).
Mat3 deformation_gradient(const ElementSet& elements, int element, std::span<const Vec3> x);

// One value per tet, in element order.
std::vector<double> tet_volume_ratio(const ElementSet& elements, std::span<const Vec3> x);
std::vector<double> tet_von_mises(const ElementSet& elements, std::span<const Vec3> x);

}  // namespace ccm::fields
