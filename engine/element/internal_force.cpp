#include "engine/element/internal_force.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "engine/material/linear_elastic.hpp"
#include "engine/material/neo_hookean.hpp"

namespace ccm {
namespace {

// cof(F) = det(F) F^-T, columns f1 x f2 ... arranged so that F^T cof(F) = det(F) I.
inline Mat3 cofactor(const Mat3& F) {
  Mat3 C;
  C.col(0) = F.col(1).cross(F.col(2));
  C.col(1) = F.col(2).cross(F.col(0));
  C.col(2) = F.col(0).cross(F.col(1));
  return C;
}

struct Accumulator {
  double min_ratio2 = std::numeric_limits<double>::infinity();  // min (h/c)^2 * c^2 = h^2
  double min_J = std::numeric_limits<double>::infinity();
  int first_bad = -1;
  double bad_J = 0.0;
  double energy = 0.0;  // of the current block
};

enum class WithEnergy { no, yes };

template <MaterialModel Model, WithEnergy Energy>
void block_forces(const ElementSet& es, const ElementBlock& b, std::span<const Vec3> x,
                  std::span<Vec3> f, Accumulator& acc) {
  double min_h2 = std::numeric_limits<double>::infinity();
  const int end = b.first + b.count;
  for (int e = b.first; e < end; ++e) {
    const Tet& t = es.tets[static_cast<size_t>(e)];
    const TetReference& ref = es.reference[static_cast<size_t>(e)];
    const Mat3 Ds = edge_matrix(x[t[0]], x[t[1]], x[t[2]], x[t[3]]);

    // Stable step of the current tet: h_e^2 = det(Ds)^2 / sum_f |n_f|^2 (tet4.hpp,
    // characteristic_length); the face normals n_f are the columns of cof(Ds) and their sum.
    const Vec3 n0 = Ds.col(1).cross(Ds.col(2));
    const Vec3 n1 = Ds.col(2).cross(Ds.col(0));
    const Vec3 n2 = Ds.col(0).cross(Ds.col(1));
    const double det_Ds = Ds.col(0).dot(n0);
    const double sum_n2 =
        n0.squaredNorm() + n1.squaredNorm() + n2.squaredNorm() + (n0 + n1 + n2).squaredNorm();
    const double h2 = det_Ds * det_Ds / sum_n2;
    min_h2 = std::min(min_h2, h2);

    const Mat3 F = Ds * ref.Dm_inv;  // F = Ds Dm^-1
    const double J = det_Ds / (6.0 * ref.V0);  // J = det F = V / V0
    if (!(J > 0.0)) [[unlikely]] {
      if (acc.first_bad < 0) {
        acc.first_bad = e;
        acc.bad_J = J;
      }
      continue;
    }
    acc.min_J = std::min(acc.min_J, J);

    Mat3 P;
    if constexpr (Model == MaterialModel::neo_hookean) {
      P = neo_hookean::first_piola(F, cofactor(F), J, b.lame);
      if constexpr (Energy == WithEnergy::yes)
        acc.energy += ref.V0 * neo_hookean::strain_energy_density(F, J, b.lame);
    } else {
      P = linear_elastic::stress(F, b.lame);
      if constexpr (Energy == WithEnergy::yes)
        acc.energy += ref.V0 * linear_elastic::strain_energy_density(F, b.lame);
    }

    // f_a = -V0 P grad N_a: columns of H = -V0 P Dm^-T for a = 1..3   (EQUATIONS.md, tet)
    const Mat3 H = (-ref.V0) * P * ref.Dm_inv.transpose();
    f[t[1]] += H.col(0);
    f[t[2]] += H.col(1);
    f[t[3]] += H.col(2);
    f[t[0]] -= H.col(0) + H.col(1) + H.col(2);
  }
  // dt_e = h_e / c_d is monotone in h for one material: one sqrt per block.
  acc.min_ratio2 = std::min(acc.min_ratio2, min_h2 / (b.wave_speed * b.wave_speed));
}

template <WithEnergy Energy>
void dispatch(const ElementSet& es, const ElementBlock& b, std::span<const Vec3> x,
              std::span<Vec3> f, Accumulator& acc) {
  if (b.model == MaterialModel::neo_hookean)
    block_forces<MaterialModel::neo_hookean, Energy>(es, b, x, f, acc);
  else
    block_forces<MaterialModel::linear_elastic, Energy>(es, b, x, f, acc);
}

}  // namespace

ElementSet make_element_set(const ModelMesh& mesh) {
  ElementSet es;
  es.tets = mesh.tets;
  es.reference.reserve(mesh.tets.size());
  for (size_t e = 0; e < mesh.tets.size(); ++e) {
    const Tet& t = mesh.tets[e];
    auto ref = make_tet_reference(mesh.X[t[0]], mesh.X[t[1]], mesh.X[t[2]], mesh.X[t[3]]);
    if (!ref)
      throw std::runtime_error(
          fmt::format("element {} (body '{}') has no positive reference volume", e,
                      mesh.bodies[static_cast<size_t>(mesh.element_body[e])].name));
    es.reference.push_back(*ref);
  }
  for (const Body& body : mesh.bodies) {
    es.blocks.push_back({body.first_element, body.n_elements, body.material.model,
                         lame_from(body.material), dilatational_wave_speed(body.material)});
  }
  return es;
}

InternalForceResult add_internal_forces(const ElementSet& elements, std::span<const Vec3> x,
                                        std::span<Vec3> f, std::span<double> block_energy) {
  Accumulator acc;
  for (size_t i = 0; i < elements.blocks.size(); ++i) {
    const ElementBlock& b = elements.blocks[i];
    if (block_energy.empty()) {
      dispatch<WithEnergy::no>(elements, b, x, f, acc);
    } else {
      acc.energy = 0.0;
      dispatch<WithEnergy::yes>(elements, b, x, f, acc);
      block_energy[i] = acc.energy;
    }
  }
  InternalForceResult r;
  r.stable_dt = std::sqrt(acc.min_ratio2);
  r.min_J = acc.min_J;
  r.first_bad_element = acc.first_bad;
  r.bad_J = acc.bad_J;
  return r;
}

double reference_stable_dt(const ElementSet& elements, std::span<const Vec3> X) {
  double min_dt = std::numeric_limits<double>::infinity();
  for (const ElementBlock& b : elements.blocks) {
    for (int e = b.first; e < b.first + b.count; ++e) {
      const Tet& t = elements.tets[static_cast<size_t>(e)];
      const double h = characteristic_length(edge_matrix(X[t[0]], X[t[1]], X[t[2]], X[t[3]]));
      min_dt = std::min(min_dt, h / b.wave_speed);
    }
  }
  return min_dt;
}

}  // namespace ccm
