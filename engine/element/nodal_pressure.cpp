#include "engine/element/nodal_pressure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "engine/element/lanes.hpp"

namespace ccm {
namespace {

#define CCM_NP_INLINE inline __attribute__((always_inline))

CCM_NP_INLINE Lanes np_load(const double (&a)[kLanes]) {
  Lanes v;
  std::memcpy(&v, a, sizeof v);
  return v;
}

CCM_NP_INLINE Lanes np_broadcast(double s) { return Lanes{} + s; }

bool is_nodal_pressure(const ElementBlock& b) { return b.element == ElementKind::nodal_pressure; }

bool any_nodal_pressure(const ElementSet& es) {
  return std::any_of(es.blocks.begin(), es.blocks.end(), is_nodal_pressure);
}

// Edges e[c][r] = x_{c+1,r} - x_{0,r} (the columns of Ds) of a pack's elements.
CCM_NP_INLINE void np_gather_edges(const NeoHookeanPack& p, const PaddedVec3* x, Lanes (&e)[3][3]) {
  Lanes x0[3];
  gather_xyz(x, p.node[0], x0[0], x0[1], x0[2]);
  for (int c = 0; c < 3; ++c) {
    gather_xyz(x, p.node[c + 1], e[c][0], e[c][1], e[c][2]);
    for (int r = 0; r < 3; ++r) e[c][r] -= x0[r];
  }
}

// n_c = e_{c+1} x e_{c+2}: the columns of cof(Ds) = 6 dV_e / dx_{c+1} (eq. NP.4).
CCM_NP_INLINE void face_normals(const Lanes (&e)[3][3], Lanes (&n)[3][3]) {
  for (int c = 0; c < 3; ++c) {
    const Lanes* a = e[(c + 1) % 3];
    const Lanes* b = e[(c + 2) % 3];
    n[c][0] = a[1] * b[2] - a[2] * b[1];
    n[c][1] = a[2] * b[0] - a[0] * b[2];
    n[c][2] = a[0] * b[1] - a[1] * b[0];
  }
}

CCM_NP_INLINE Lanes det_of(const Lanes (&e)[3][3], const Lanes (&n)[3][3]) {
  return e[0][0] * n[0][0] + e[0][1] * n[0][1] + e[0][2] * n[0][2];
}

// Pass 1 for one slab: V_n += V_e / 4 at the four nodes of each element (eq. NP.2), lane by
// lane, nodes 0..3: the fixed order every thread count shares. V_n is summed in the fourth slot
// of the node's row (rows[n].v[3]): 32 bytes per node as the forces have, so that two threads
// scattering into the nodes of two slabs of one phase seldom write one cache line (with V_n
// packed 8 to a line they did, on most lines, and pass 1 scaled poorly on two threads).
void scatter_slab_volumes(const ElementBlock& b, const Slab& slab, const PaddedVec3* x,
                          PaddedVec3* rows) {
  const int end = slab.first_pack + slab.n_packs;
  for (int i = slab.first_pack; i < end; ++i) {
    const NeoHookeanPack& p = b.neo_hookean_packs[static_cast<size_t>(i)];
    const int lanes = i + 1 == end ? slab.last_lanes : kLanes;
    Lanes e[3][3], n[3][3];
    np_gather_edges(p, x, e);
    face_normals(e, n);
    const Lanes quarter_volume = det_of(e, n) * (1.0 / 24.0);  // det(Ds) / 6 / 4
    for (int l = 0; l < lanes; ++l)
      for (int a = 0; a < 4; ++a) rows[p.node[a][l]].v[3] += quarter_volume[l];
  }
}

// Pass 2 for nodes [first, first + count) of a block, kLanes at a time: J_n = V_n / V0_n with
// V_n from the fourth slot of the row (pass 1), kept in d.V for the energy; p_n = U'(J_n) =
// lambda ln(J_n) / J_n (eq. NP.3), stored with the node's position as the row (x, y, z, p_n);
// returns the largest |ln J_n| (eq. NP.6). A node with J_n <= 0 (only next to an inverted
// element, which the element pass reports) gets p_n = 0.
double nodal_pressures(const NodalPressureData& d, const PaddedVec3* x, double lambda, int first,
                       int count) {
  PaddedVec3* rows = d.position_pressure.data();
  const int lanes = std::min(count, kLanes);
  Lanes J{};
  for (int l = 0; l < kLanes; ++l) {
    const auto n = static_cast<size_t>(first + std::min(l, count - 1));
    J[l] = d.V0[n] > 0.0 ? rows[n].v[3] / d.V0[n] : 1.0;  // V0_n = 0: a node of no element
  }
  for (int l = 0; l < lanes; ++l) {
    const auto n = static_cast<size_t>(first + l);
    d.V[n] = rows[n].v[3];
  }
  const Lanes log_J = kernel_log(J > 0.0 ? J : np_broadcast(1.0));
  const Lanes p = lambda * log_J / J;
  double max_abs_log_J = 0.0;
  for (int l = 0; l < lanes; ++l) {
    const auto n = static_cast<size_t>(first + l);
    rows[n] = {{x[n].v[0], x[n].v[1], x[n].v[2], p[l]}};
    max_abs_log_J = std::max(max_abs_log_J, std::abs(log_J[l]));
  }
  return max_abs_log_J;
}

// Pass 3 on one pack. The element keeps W_e = mu/2 (tr C - 3) - mu ln J_e, whose nodal forces
// are those of the plain kernel with lambda = 0 (internal_force.cpp):
//   H = -mu V0 Ds G + mu V0 cof(Ds) / det(Ds),
// and the nodal volumetric energy adds -pbar_e dV_e/dx_a = -pbar_e n_c / 6 (eq. NP.4), with
// pbar_e the mean of the four nodal pressures.
struct NodalPressureForces {
  Lanes h[3][3];  // forces on local nodes 1..3; node 0 takes minus their sum
  Lanes J;
  Lanes y;  // sum_f |n_f|^2 M / det(Ds)^2 = rho / dt_e^2 with M of eq. NP.6
  Lanes W;  // V0_e W_e
};

// The edges of Ds (as np_gather_edges) and the mean of the four nodal pressures, pbar_e, from
// one move per node of the (x, y, z, p_n) rows.
CCM_NP_INLINE Lanes gather_edges_and_mean_pressure(const NeoHookeanPack& p,
                                                   const PaddedVec3* position_pressure,
                                                   Lanes (&e)[3][3]) {
  Lanes x0[3], p_node[4];
  gather_xyzw(position_pressure, p.node[0], x0[0], x0[1], x0[2], p_node[0]);
  for (int c = 0; c < 3; ++c) {
    gather_xyzw(position_pressure, p.node[c + 1], e[c][0], e[c][1], e[c][2], p_node[c + 1]);
    for (int r = 0; r < 3; ++r) e[c][r] -= x0[r];
  }
  return 0.25 * ((p_node[0] + p_node[1]) + (p_node[2] + p_node[3]));
}

template <bool Energy>
CCM_NP_INLINE NodalPressureForces element_forces(const NeoHookeanPack& p,
                                                 const PaddedVec3* position_pressure,
                                                 const Lame& lame, double max_abs_log_J) {
  Lanes e[3][3], n[3][3];
  const Lanes p_mean = gather_edges_and_mean_pressure(p, position_pressure, e);
  face_normals(e, n);
  const Lanes V0 = np_load(p.V0);
  const Lanes det = det_of(e, n);
  const Lanes six_V0 = 6.0 * V0;
  const Lanes q = 1.0 / (det * six_V0);  // one division for 1 / det and J = det / (6 V0)
  const Lanes inv_det = q * six_V0;
  NodalPressureForces out;
  out.J = det * det * q;
  const Lanes g00 = np_load(p.geometry[0]), g11 = np_load(p.geometry[1]);
  const Lanes g22 = np_load(p.geometry[2]), g01 = np_load(p.geometry[3]);
  const Lanes g02 = np_load(p.geometry[4]), g12 = np_load(p.geometry[5]);
  const Lanes mu = np_broadcast(lame.mu);
  const Lanes A = -mu * V0;
  const Lanes B = mu * V0 * inv_det - p_mean * (1.0 / 6.0);
  Lanes trC = np_broadcast(0.0);
  for (int r = 0; r < 3; ++r) {
    const Lanes d0 = e[0][r], d1 = e[1][r], d2 = e[2][r];  // row r of Ds
    const Lanes dg0 = d0 * g00 + d1 * g01 + d2 * g02;      // row r of Ds G
    const Lanes dg1 = d0 * g01 + d1 * g11 + d2 * g12;
    const Lanes dg2 = d0 * g02 + d1 * g12 + d2 * g22;
    trC += d0 * dg0 + d1 * dg1 + d2 * dg2;
    out.h[0][r] = A * dg0 + B * n[0][r];
    out.h[1][r] = A * dg1 + B * n[1][r];
    out.h[2][r] = A * dg2 + B * n[2][r];
  }
  if constexpr (Energy) {  // the forces need no ln J_e: only the energy does
    const Lanes log_J = kernel_log(out.J > 0.0 ? out.J : np_broadcast(1.0));
    out.W = V0 * (0.5 * mu * (trC - 3.0) - mu * log_J);
  }
  Lanes sum_n2 = np_broadcast(0.0);  // sum_f |n_f|^2 = det^2 / h_e^2 (tet4.hpp)
  for (int k = 0; k < 3; ++k) {
    const Lanes t = n[0][k] + n[1][k] + n[2][k];
    sum_n2 += n[0][k] * n[0][k] + n[1][k] * n[1][k] + n[2][k] * n[2][k] + t * t;
  }
  // eq. NP.6: the plain kernel's current-state modulus with the element's |ln J| replaced by the
  // largest nodal |ln J_n| of the block (a bound on the mean over the element's nodes).
  const Lanes stretch = trC > 3.0 ? trC - 3.0 : np_broadcast(0.0);
  const Lanes M = lame.lambda * (1.0 + 2.0 * max_abs_log_J) + mu * (2.0 + stretch);
  out.y = sum_n2 * M * (inv_det * inv_det);
  return out;
}

// Per-lane running values over a slab, reduced once at its end (as the plain kernel does).
struct LaneRunning {
  Lanes max_y = np_broadcast(0.0);
  Lanes min_J = np_broadcast(std::numeric_limits<double>::infinity());
  Lanes energy = np_broadcast(0.0);
};

template <bool Energy>
void account_pack(const ElementBlock& b, int pack, const NodalPressureForces& r, int lanes,
                  LaneRunning& t, SlabTotals& slab) {
  t.max_y = r.y > t.max_y ? r.y : t.max_y;  // a NaN y is left out: its J reports it
  const auto good = r.J > 0.0;
  t.min_J = good && r.J < t.min_J ? r.J : t.min_J;
  if constexpr (Energy) {
    Lanes W = r.W;
    for (int l = lanes; l < kLanes; ++l) W[l] = 0.0;
    t.energy += W;
  }
  for (int l = 0; l < lanes; ++l) {
    if (good[l]) continue;
    const int e = b.lane_element[static_cast<size_t>(pack * kLanes + l)];
    if (slab.first_bad < 0 || e < slab.first_bad) {
      slab.first_bad = e;
      slab.bad_J = r.J[l];
    }
  }
}

template <bool Energy>
SlabTotals run_slab(const ElementBlock& b, const Slab& slab, const PaddedVec3* position_pressure,
                    double max_abs_log_J, PaddedVec3* f) {
  SlabTotals out;
  LaneRunning t;
  const int end = slab.first_pack + slab.n_packs;
  for (int i = slab.first_pack; i < end; ++i) {
    const NeoHookeanPack& p = b.neo_hookean_packs[static_cast<size_t>(i)];
    const int lanes = i + 1 == end ? slab.last_lanes : kLanes;
    const NodalPressureForces r =
        element_forces<Energy>(p, position_pressure, b.lame, max_abs_log_J);
    scatter_forces(p.node, r.h, lanes, f);
    account_pack<Energy>(b, i, r, lanes, t, out);
  }
  for (int l = 0; l < kLanes; ++l) {
    out.max_y = std::max(out.max_y, t.max_y[l]);
    out.min_J = std::min(out.min_J, t.min_J[l]);
    out.energy += t.energy[l];
  }
  return out;
}

}  // namespace

void prepare_nodal_pressure(ElementSet& es, const ModelMesh& mesh) {
  if (!any_nodal_pressure(es)) return;
  const auto n_nodes = static_cast<size_t>(mesh.n_nodes());
  es.nodal.V0.assign(n_nodes, 0.0);
  es.nodal.V.assign(n_nodes, 0.0);
  es.nodal.position_pressure.assign(n_nodes, PaddedVec3{});
  es.nodal.max_abs_log_J.assign(es.blocks.size(), 0.0);
  for (size_t k = 0; k < es.blocks.size(); ++k) {
    const ElementBlock& b = es.blocks[k];
    if (!is_nodal_pressure(b)) continue;
    if (b.model != MaterialModel::neo_hookean)
      throw std::runtime_error(
          fmt::format("body '{}': element nodal_pressure needs material model neo_hookean",
                      mesh.bodies[k].name));
    for (int e = b.first; e < b.first + b.count; ++e)  // eq. NP.1
      for (int n : es.tets[static_cast<size_t>(e)])
        es.nodal.V0[static_cast<size_t>(n)] += 0.25 * es.reference[static_cast<size_t>(e)].V0;
  }
}

void update_nodal_pressures(const ElementSet& es, const PaddedVec3* x) {
  if (es.nodal.empty()) return;
  const NodalPressureData& d = es.nodal;
  PaddedVec3* rows = d.position_pressure.data();
  const ElementSchedule& schedule = es.schedule;
#pragma omp single nowait
  std::fill(d.max_abs_log_J.begin(), d.max_abs_log_J.end(), 0.0);
  for (const ElementBlock& b : es.blocks) {
    if (!is_nodal_pressure(b)) continue;
#pragma omp for schedule(static) nowait
    for (int n = b.first_node; n < b.first_node + b.n_nodes; ++n) rows[n].v[3] = 0.0;
  }
#pragma omp barrier
  // Pass 1 in the phases of the force loop: the slabs of one phase share no node.
  for (const std::vector<int>& phase : schedule.phases) {
#pragma omp for schedule(dynamic, 1)
    for (size_t k = 0; k < phase.size(); ++k) {
      const Slab& slab = schedule.slabs[static_cast<size_t>(phase[k])];
      const ElementBlock& b = es.blocks[static_cast<size_t>(slab.block)];
      if (is_nodal_pressure(b)) scatter_slab_volumes(b, slab, x, rows);
    }
  }
  // Pass 2: the blocks' node ranges are disjoint, so no barrier between them; a maximum is
  // exact, so the order in which the threads' maxima combine does not matter.
  for (size_t k = 0; k < es.blocks.size(); ++k) {
    const ElementBlock& b = es.blocks[k];
    if (!is_nodal_pressure(b)) continue;
    const int chunks = (b.n_nodes + kLanes - 1) / kLanes;
    double thread_max = 0.0;
#pragma omp for schedule(static) nowait
    for (int c = 0; c < chunks; ++c)
      thread_max = std::max(
          thread_max,
          nodal_pressures(d, x, b.lame.lambda, b.first_node + c * kLanes, b.n_nodes - c * kLanes));
#pragma omp critical(ccm_nodal_pressure_max)
    d.max_abs_log_J[k] = std::max(d.max_abs_log_J[k], thread_max);
  }
  // Pass 3 reads every row and maximum.
#pragma omp barrier
}

SlabTotals run_nodal_pressure_slab(const ElementSet& es, const ElementBlock& block,
                                   const Slab& slab, PaddedVec3* f, bool with_energy) {
  const PaddedVec3* position_pressure = es.nodal.position_pressure.data();
  const double max_abs_log_J =
      es.nodal.max_abs_log_J[static_cast<size_t>(&block - es.blocks.data())];
  return with_energy ? run_slab<true>(block, slab, position_pressure, max_abs_log_J, f)
                     : run_slab<false>(block, slab, position_pressure, max_abs_log_J, f);
}

void add_nodal_volumetric_energy(const ElementSet& es, std::span<double> block_energy) {
  for (size_t k = 0; k < es.blocks.size(); ++k) {
    const ElementBlock& b = es.blocks[k];
    if (!is_nodal_pressure(b)) continue;
    double sum = 0.0;
    for (int i = b.first_node; i < b.first_node + b.n_nodes; ++i) {
      const auto n = static_cast<size_t>(i);
      if (es.nodal.V0[n] <= 0.0) continue;  // a node of no element
      const double J = es.nodal.V[n] / es.nodal.V0[n];
      const double log_J = J > 0.0 ? std::log(J) : 0.0;             // J_n <= 0: as in pass 2
      sum += es.nodal.V0[n] * 0.5 * b.lame.lambda * log_J * log_J;  // V0_n U(J_n), eq. NP.2
    }
    block_energy[k] += sum;
  }
}

}  // namespace ccm
