#include "engine/element/internal_force.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "engine/element/lanes.hpp"

namespace ccm {
namespace {

enum class WithEnergy { no, yes };

// Per-lane results of one pack, reduced and scattered after the vector code.
struct PackResult {
  double f[4][3][kLanes];  // f[a][i]: component i of the force on local node a
  double h2[kLanes];       // squared characteristic length, scaled to the reference wave speed
  double J[kLanes];
  double W[kLanes];  // V0 * strain energy density (only WithEnergy::yes)
};

struct Accumulator {
  double min_ratio2 = std::numeric_limits<double>::infinity();  // min_e (h_e / c_d,e)^2
  double min_J = std::numeric_limits<double>::infinity();
  int first_bad = -1;
  double bad_J = 0.0;
  double energy = 0.0;  // of the current block
};

inline Lanes load(const double (&a)[kLanes]) {
  Lanes v;
  std::memcpy(&v, a, sizeof v);
  return v;
}

inline void store(double (&a)[kLanes], Lanes v) { std::memcpy(a, &v, sizeof v); }

inline Lanes broadcast(double s) { return Lanes{} + s; }

// Component k of node a of every lane, gathered from x (3 n doubles).
inline Lanes gather(const ElementPack& p, int a, int k, const double* x) {
  Lanes v;
  for (int l = 0; l < kLanes; ++l) v[l] = x[3 * p.node[a][l] + k];
  return v;
}

// The element kernel on kLanes elements at once. Notation: e_c = x_{c+1} - x_0 (columns of
// Ds), F = Ds Dm^-1, n_f the face normals scaled by twice the face area.
template <MaterialModel Model, WithEnergy Energy>
void pack_kernel(const ElementPack& p, const double* x, const Lame& lame, PackResult& out) {
  Lanes e[3][3];  // e[c][r]: component r of edge c
  for (int r = 0; r < 3; ++r) {
    const Lanes x0 = gather(p, 0, r, x);
    for (int c = 0; c < 3; ++c) e[c][r] = gather(p, c + 1, r, x) - x0;
  }
  // n0 = e1 x e2 ... cyclic: n_c = e_{c+1} x e_{c+2}; the fourth face is -(n0 + n1 + n2).
  Lanes n[3][3];
  for (int c = 0; c < 3; ++c) {
    const Lanes* a = e[(c + 1) % 3];
    const Lanes* b = e[(c + 2) % 3];
    n[c][0] = a[1] * b[2] - a[2] * b[1];
    n[c][1] = a[2] * b[0] - a[0] * b[2];
    n[c][2] = a[0] * b[1] - a[1] * b[0];
  }
  const Lanes det = e[0][0] * n[0][0] + e[0][1] * n[0][1] + e[0][2] * n[0][2];
  Lanes sum_n2 = broadcast(0.0);
  for (int k = 0; k < 3; ++k) {
    const Lanes s = n[0][k] + n[1][k] + n[2][k];
    sum_n2 += n[0][k] * n[0][k] + n[1][k] * n[1][k] + n[2][k] * n[2][k] + s * s;
  }
  const Lanes h2 = det * det / sum_n2;  // h_e^2 = det(Ds)^2 / sum_f |n_f|^2   (tet4.hpp)

  Lanes Dm[9];
  for (int k = 0; k < 9; ++k) Dm[k] = load(p.Dm_inv[k]);
  Lanes F[3][3];  // F(i, c) = sum_k Ds(i, k) Dm^-1(k, c)
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c)
      F[i][c] = e[0][i] * Dm[c] + e[1][i] * Dm[3 + c] + e[2][i] * Dm[6 + c];
  const Lanes J = det * load(p.inv_6V0);  // J = det F = V / V0
  store(out.J, J);

  Lanes P[3][3];
  Lanes W = broadcast(0.0);
  const Lanes mu = broadcast(lame.mu), lambda = broadcast(lame.lambda);
  if constexpr (Model == MaterialModel::neo_hookean) {
    // cof(F) columns: F_1 x F_2, F_2 x F_0, F_0 x F_1 (F_c = column c): F^-T = cof(F) / J.
    Lanes C[3][3];
    for (int c = 0; c < 3; ++c) {
      const int a = (c + 1) % 3, b = (c + 2) % 3;
      C[0][c] = F[1][a] * F[2][b] - F[2][a] * F[1][b];
      C[1][c] = F[2][a] * F[0][b] - F[0][a] * F[2][b];
      C[2][c] = F[0][a] * F[1][b] - F[1][a] * F[0][b];
    }
    const Lanes log_J = vector_log(J > 0.0 ? J : broadcast(1.0));  // bad lanes: reported only
    // P = mu F + (lambda ln J - mu) F^-T   (eq. 2.3; neo_hookean.hpp)
    const Lanes k = (lambda * log_J - mu) / J;
    Lanes trC = broadcast(0.0);
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) {
        P[i][c] = mu * F[i][c] + k * C[i][c];
        trC += F[i][c] * F[i][c];
      }
    if constexpr (Energy == WithEnergy::yes)  // W = lambda/2 ln^2 J - mu ln J + mu/2 (tr C - 3)
      W = 0.5 * lambda * log_J * log_J - mu * log_J + 0.5 * mu * (trC - 3.0);
    // Stiffening under compression: the wave speed uses the tangent modulus of the current
    // state, M = lambda (1 + 2 |ln J|) + mu (2 + max(tr C - 3, 0)) (docs/time-step.md), so
    // h_e^2 is scaled by (lambda + 2 mu) / M before it is divided by c_d^2 of the block.
    const Lanes abs_log_J = log_J < 0.0 ? -log_J : log_J;
    const Lanes stretch = trC > 3.0 ? trC - 3.0 : broadcast(0.0);
    const Lanes M = lambda * (1.0 + 2.0 * abs_log_J) + mu * (2.0 + stretch);
    store(out.h2, h2 * (lambda + 2.0 * mu) / M);
  } else {
    // sigma = lambda tr(eps) I + 2 mu eps, eps = sym(F - I)   (eq. 2.1; linear_elastic.hpp)
    const Lanes tr = F[0][0] + F[1][1] + F[2][2] - 3.0;
    Lanes eps_sq = broadcast(0.0);
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) {
        const Lanes eps = 0.5 * (F[i][c] + F[c][i]) - (i == c ? 1.0 : 0.0);
        P[i][c] = 2.0 * mu * eps + (i == c ? lambda * tr : broadcast(0.0));
        eps_sq += eps * eps;
      }
    if constexpr (Energy == WithEnergy::yes) W = 0.5 * lambda * tr * tr + mu * eps_sq;
    store(out.h2, h2);  // small strain: the reference moduli
  }
  const Lanes V0 = load(p.V0);
  if constexpr (Energy == WithEnergy::yes) store(out.W, V0 * W);

  // f_a = -V0 P grad N_a: for a = 1..3 the columns of H = -V0 P Dm^-T,
  // H(i, a) = -V0 sum_c P(i, c) Dm^-1(a, c); f_0 = -(f_1 + f_2 + f_3)   (docs/equations.md "Linear tetrahedron")
  for (int i = 0; i < 3; ++i) {
    Lanes f0 = broadcast(0.0);
    for (int a = 0; a < 3; ++a) {
      const Lanes h =
          -V0 * (P[i][0] * Dm[3 * a] + P[i][1] * Dm[3 * a + 1] + P[i][2] * Dm[3 * a + 2]);
      store(out.f[a + 1][i], h);
      f0 -= h;
    }
    store(out.f[0][i], f0);
  }
}

// Adds the pack's nodal forces into the global f; sequential, since lanes may share nodes.
void scatter(const ElementPack& p, const PackResult& r, double* f) {
  for (int l = 0; l < kLanes; ++l)
    for (int a = 0; a < 4; ++a) {
      double* fa = f + 3 * p.node[a][l];
      fa[0] += r.f[a][0][l];
      fa[1] += r.f[a][1][l];
      fa[2] += r.f[a][2][l];
    }
}

template <WithEnergy Energy>
void reduce(const ElementPack& p, const PackResult& r, double& min_h2, Accumulator& acc) {
  for (int l = 0; l < kLanes; ++l) {
    min_h2 = std::min(min_h2, r.h2[l]);
    if (!(r.J[l] > 0.0)) [[unlikely]] {
      if (acc.first_bad < 0) {
        acc.first_bad = p.element[l];
        acc.bad_J = r.J[l];
      }
    } else {
      acc.min_J = std::min(acc.min_J, r.J[l]);
    }
    if constexpr (Energy == WithEnergy::yes) acc.energy += r.W[l];
  }
}

template <MaterialModel Model, WithEnergy Energy>
void block_forces(const ElementBlock& b, const double* x, double* f, Accumulator& acc) {
  double min_h2 = std::numeric_limits<double>::infinity();
  PackResult r;
  for (const ElementPack& p : b.packs) {
    pack_kernel<Model, Energy>(p, x, b.lame, r);
    scatter(p, r, f);
    reduce<Energy>(p, r, min_h2, acc);
  }
  // dt_e = h_e / c_d is monotone in h for one material: one division per block.
  acc.min_ratio2 = std::min(acc.min_ratio2, min_h2 / (b.wave_speed * b.wave_speed));
}

template <WithEnergy Energy>
void dispatch(const ElementBlock& b, const double* x, double* f, Accumulator& acc) {
  if (b.model == MaterialModel::neo_hookean)
    block_forces<MaterialModel::neo_hookean, Energy>(b, x, f, acc);
  else
    block_forces<MaterialModel::linear_elastic, Energy>(b, x, f, acc);
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
    es.blocks.push_back(
        {body.first_element, body.n_elements, body.material.model, lame_from(body.material),
         dilatational_wave_speed(body.material),
         make_element_packs(es.tets, es.reference, body.first_element, body.n_elements)});
  }
  return es;
}

InternalForceResult add_internal_forces(const ElementSet& elements, std::span<const Vec3> x,
                                        std::span<Vec3> f, std::span<double> block_energy) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
  const double* xp = x.data()->data();
  double* fp = f.data()->data();
  Accumulator acc;
  for (size_t i = 0; i < elements.blocks.size(); ++i) {
    const ElementBlock& b = elements.blocks[i];
    if (b.count == 0) continue;
    if (block_energy.empty()) {
      dispatch<WithEnergy::no>(b, xp, fp, acc);
    } else {
      acc.energy = 0.0;
      dispatch<WithEnergy::yes>(b, xp, fp, acc);
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
