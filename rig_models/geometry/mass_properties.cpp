#include "rig_models/geometry/mass_properties.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace ccm::rig {

std::vector<UnitMass> unit_mass_properties(const TetMesh& mesh, const Vec3& point,
                                           const Vec3& direction) {
  const Vec3 e = direction.normalized();
  std::vector<UnitMass> out(std::max<size_t>(mesh.region_names.size(), 1));
  for (size_t k = 0; k < mesh.tets.size(); ++k) {
    const Tet& t = mesh.tets[k];
    const auto& x = mesh.nodes;
    const double V = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).dot(x[t[3]] - x[t[0]]) / 6.0;
    UnitMass& u = out[mesh.tet_region.empty() ? 0 : static_cast<size_t>(mesh.tet_region[k])];
    u.volume += V;
    for (int n : t) {
      const Vec3 d = x[static_cast<size_t>(n)] - point;
      const Vec3 perp = d - d.dot(e) * e;
      u.inertia += V / 4.0 * perp.squaredNorm();
      u.first_moment += V / 4.0 * x[static_cast<size_t>(n)];
    }
  }
  return out;
}

DensityPair densities_for(const UnitMass& a, const UnitMass& b, double M, double J, double m_fixed,
                          double I_fixed) {
  const double m = M - m_fixed, I = J - I_fixed;
  const double det = a.volume * b.inertia - b.volume * a.inertia;
  if (!(std::abs(det) > 0.0))
    throw std::invalid_argument("density tuning: the two parts have the same radius of gyration");
  const DensityPair d{(m * b.inertia - b.volume * I) / det, (a.volume * I - m * a.inertia) / det};
  if (!(d.rho_a > 0.0 && d.rho_b > 0.0))
    throw std::invalid_argument(fmt::format(
        "density tuning: mass {:.4g} kg and inertia {:.4g} kg m^2 need densities {:.4g} and "
        "{:.4g} kg/m^3; the geometry cannot carry them (parts of radius of gyration {:.4g} and "
        "{:.4g} m, {:.4g} kg and {:.4g} kg m^2 fixed)",
        M, J, d.rho_a, d.rho_b, std::sqrt(a.inertia / a.volume), std::sqrt(b.inertia / b.volume),
        m_fixed, I_fixed));
  return d;
}

}  // namespace ccm::rig
