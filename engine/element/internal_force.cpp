#include "engine/element/internal_force.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "engine/element/lanes.hpp"
#include "engine/element/nodal_pressure.hpp"
#include "engine/element/slab_totals.hpp"

namespace ccm {
namespace {

enum class WithEnergy { no, yes };

#define CCM_INLINE inline __attribute__((always_inline))

CCM_INLINE Lanes load(const double (&a)[kLanes]) {
  Lanes v;
  std::memcpy(&v, a, sizeof v);
  return v;
}

CCM_INLINE Lanes broadcast(double s) { return Lanes{} + s; }

// What one pack's kernel hands on: the forces on local nodes 1..3 (h[a][i], component i of the
// force on node a + 1; node 0 takes minus their sum), J, the stable-step measure y and V0 W.
struct PackForces {
  Lanes h[3][3];
  Lanes J;
  Lanes y;  // sum_f |n_f|^2 M / det(Ds)^2 = rho / dt_e^2: the largest y sets the stable step
  Lanes W;  // V0 x strain energy density (WithEnergy::yes only)
};

// Edges e[c][r] = x_{c+1,r} - x_{0,r} (the columns of Ds), gathered from the padded nodes x.
template <class Pack>
CCM_INLINE void gather_edges(const Pack& p, const PaddedVec3* x, Lanes (&e)[3][3]) {
  Lanes x0[3];
  gather_xyz(x, p.node[0], x0[0], x0[1], x0[2]);
  for (int c = 0; c < 3; ++c) {
    gather_xyz(x, p.node[c + 1], e[c][0], e[c][1], e[c][2]);
    for (int r = 0; r < 3; ++r) e[c][r] -= x0[r];
  }
}

// Shared by both models: the face normals n_c = e_{c+1} x e_{c+2} (the columns of cof(Ds); the
// fourth face is -(n0 + n1 + n2)), det(Ds), 1 / det(Ds) and J = det(Ds) / (6 V0) from one
// division, and sum_f |n_f|^2 = det(Ds)^2 / h_e^2 (tet4.hpp).
struct Shape {
  Lanes n[3][3];  // n[c][r]
  Lanes det, inv_det, J, sum_n2;
};

CCM_INLINE Shape shape_of(const Lanes (&e)[3][3], Lanes V0) {
  Shape s;
  for (int c = 0; c < 3; ++c) {
    const Lanes* a = e[(c + 1) % 3];
    const Lanes* b = e[(c + 2) % 3];
    s.n[c][0] = a[1] * b[2] - a[2] * b[1];
    s.n[c][1] = a[2] * b[0] - a[0] * b[2];
    s.n[c][2] = a[0] * b[1] - a[1] * b[0];
  }
  s.det = e[0][0] * s.n[0][0] + e[0][1] * s.n[0][1] + e[0][2] * s.n[0][2];
  const Lanes six_V0 = 6.0 * V0;
  const Lanes q = 1.0 / (s.det * six_V0);
  s.inv_det = q * six_V0;
  s.J = s.det * s.det * q;
  s.sum_n2 = broadcast(0.0);
  for (int k = 0; k < 3; ++k) {
    const Lanes t = s.n[0][k] + s.n[1][k] + s.n[2][k];
    s.sum_n2 += s.n[0][k] * s.n[0][k] + s.n[1][k] * s.n[1][k] + s.n[2][k] * s.n[2][k] + t * t;
  }
  return s;
}

// Compressible Neo-Hookean (eq. 2.3; neo_hookean.hpp): P = mu F + (lambda ln J - mu) F^-T, so
// with F = Ds Dm^-1 and G = Dm^-1 Dm^-T the nodal forces are
//   H = -V0 P Dm^-T = -mu V0 Ds G + V0 (mu - lambda ln J) cof(Ds) / det(Ds)
// (F^-T Dm^-T = Ds^-T), and tr C = tr(F^T F) = sum_rc Ds_rc (Ds G)_rc.
template <WithEnergy Energy>
CCM_INLINE PackForces neo_hookean_pack(const NeoHookeanPack& p, const PaddedVec3* x,
                                       const Lame& lame) {
  Lanes e[3][3];
  gather_edges(p, x, e);
  const Lanes V0 = load(p.V0);
  const Shape s = shape_of(e, V0);
  PackForces out;
  out.J = s.J;
  const Lanes log_J = kernel_log(s.J > 0.0 ? s.J : broadcast(1.0));  // bad lanes: reported only
  const Lanes g00 = load(p.geometry[0]), g11 = load(p.geometry[1]), g22 = load(p.geometry[2]);
  const Lanes g01 = load(p.geometry[3]), g02 = load(p.geometry[4]), g12 = load(p.geometry[5]);
  const Lanes A = -lame.mu * V0;
  const Lanes B = V0 * (lame.mu - lame.lambda * log_J) * s.inv_det;
  Lanes trC = broadcast(0.0);
  for (int r = 0; r < 3; ++r) {
    const Lanes d0 = e[0][r], d1 = e[1][r], d2 = e[2][r];  // row r of Ds
    const Lanes dg0 = d0 * g00 + d1 * g01 + d2 * g02;      // row r of Ds G
    const Lanes dg1 = d0 * g01 + d1 * g11 + d2 * g12;
    const Lanes dg2 = d0 * g02 + d1 * g12 + d2 * g22;
    trC += d0 * dg0 + d1 * dg1 + d2 * dg2;
    out.h[0][r] = A * dg0 + B * s.n[0][r];
    out.h[1][r] = A * dg1 + B * s.n[1][r];
    out.h[2][r] = A * dg2 + B * s.n[2][r];
  }
  const Lanes mu = broadcast(lame.mu), lambda = broadcast(lame.lambda);
  if constexpr (Energy == WithEnergy::yes)  // W = lambda/2 ln^2 J - mu ln J + mu/2 (tr C - 3)
    out.W = V0 * (0.5 * lambda * log_J * log_J - mu * log_J + 0.5 * mu * (trC - 3.0));
  // Stiffening under compression: the wave speed uses the tangent modulus of the current state,
  // M = lambda (1 + 2 |ln J|) + mu (2 + max(tr C - 3, 0)) (docs/time-step.md).
  const Lanes abs_log_J = log_J < 0.0 ? -log_J : log_J;
  const Lanes stretch = trC > 3.0 ? trC - 3.0 : broadcast(0.0);
  const Lanes M = lambda * (1.0 + 2.0 * abs_log_J) + mu * (2.0 + stretch);
  out.y = s.sum_n2 * M * (s.inv_det * s.inv_det);
  return out;
}

// Linear elastic (eq. 2.1; linear_elastic.hpp): sigma = lambda tr(eps) I + 2 mu eps with
// eps = sym(F - I), H(i, a) = -V0 sum_c P(i, c) Dm^-1(a, c); the reference moduli set the step.
template <WithEnergy Energy>
CCM_INLINE PackForces linear_pack(const LinearPack& p, const PaddedVec3* x, const Lame& lame) {
  Lanes e[3][3];
  gather_edges(p, x, e);
  const Lanes V0 = load(p.V0);
  const Shape s = shape_of(e, V0);
  PackForces out;
  out.J = s.J;
  Lanes Dm[9];
  for (int k = 0; k < 9; ++k) Dm[k] = load(p.geometry[k]);
  Lanes F[3][3];  // F(i, c) = sum_k Ds(i, k) Dm^-1(k, c)
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c)
      F[i][c] = e[0][i] * Dm[c] + e[1][i] * Dm[3 + c] + e[2][i] * Dm[6 + c];
  const Lanes mu = broadcast(lame.mu), lambda = broadcast(lame.lambda);
  const Lanes tr = F[0][0] + F[1][1] + F[2][2] - 3.0;
  Lanes P[3][3];
  Lanes eps_sq = broadcast(0.0);
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c) {
      const Lanes eps = 0.5 * (F[i][c] + F[c][i]) - (i == c ? 1.0 : 0.0);
      P[i][c] = 2.0 * mu * eps + (i == c ? lambda * tr : broadcast(0.0));
      eps_sq += eps * eps;
    }
  if constexpr (Energy == WithEnergy::yes) out.W = V0 * (0.5 * lambda * tr * tr + mu * eps_sq);
  for (int i = 0; i < 3; ++i)
    for (int a = 0; a < 3; ++a)
      out.h[a][i] = -V0 * (P[i][0] * Dm[3 * a] + P[i][1] * Dm[3 * a + 1] + P[i][2] * Dm[3 * a + 2]);
  out.y = s.sum_n2 * (lambda + 2.0 * mu) * (s.inv_det * s.inv_det);
  return out;
}

// Per-lane running values over a slab's packs, reduced once at its end.
struct LaneTotals {
  Lanes max_y = broadcast(0.0);
  Lanes min_J = broadcast(std::numeric_limits<double>::infinity());
  Lanes energy = broadcast(0.0);
};

template <class Pack, WithEnergy Energy>
CCM_INLINE void account(const ElementBlock& b, int pack, const PackForces& r, int lanes,
                        LaneTotals& t, SlabTotals& slab) {
  t.max_y = r.y > t.max_y ? r.y : t.max_y;  // a NaN y is left out: its J reports it
  const auto good = r.J > 0.0;
  t.min_J = good && r.J < t.min_J ? r.J : t.min_J;
  if constexpr (Energy == WithEnergy::yes) {
    Lanes W = r.W;
    if (lanes < kLanes)
      for (int l = lanes; l < kLanes; ++l) W[l] = 0.0;
    t.energy += W;
  }
  bool all_good = true;
  for (int l = 0; l < kLanes; ++l) all_good &= good[l] != 0;
  if (all_good) [[likely]]
    return;
  for (int l = 0; l < lanes; ++l) {
    if (good[l]) continue;
    const int e = b.lane_element[static_cast<size_t>(pack * kLanes + l)];
    if (slab.first_bad < 0 || e < slab.first_bad) {
      slab.first_bad = e;
      slab.bad_J = r.J[l];
    }
  }
}

template <class Pack, WithEnergy Energy>
SlabTotals run_slab(const ElementBlock& b, const std::vector<Pack>& packs, const Slab& slab,
                    const PaddedVec3* x, PaddedVec3* f) {
  SlabTotals out;
  LaneTotals t;
  const int end = slab.first_pack + slab.n_packs;
  for (int i = slab.first_pack; i < end; ++i) {
    const Pack& p = packs[static_cast<size_t>(i)];
    const int lanes = i + 1 == end ? slab.last_lanes : kLanes;
    PackForces r;
    if constexpr (std::is_same_v<Pack, NeoHookeanPack>)
      r = neo_hookean_pack<Energy>(p, x, b.lame);
    else
      r = linear_pack<Energy>(p, x, b.lame);
    scatter_forces(p.node, r.h, lanes, f);
    account<Pack, Energy>(b, i, r, lanes, t, out);
  }
  for (int l = 0; l < kLanes; ++l) {
    out.max_y = std::max(out.max_y, t.max_y[l]);
    out.min_J = std::min(out.min_J, t.min_J[l]);
    out.energy += t.energy[l];
  }
  return out;
}

SlabTotals run_slab(const ElementSet& es, const ElementBlock& b, const Slab& slab,
                    const PaddedVec3* x, PaddedVec3* f, bool with_energy) {
  if (b.element == ElementKind::nodal_pressure)
    return run_nodal_pressure_slab(es, b, slab, f, with_energy);
  if (b.model == MaterialModel::neo_hookean)
    return with_energy
               ? run_slab<NeoHookeanPack, WithEnergy::yes>(b, b.neo_hookean_packs, slab, x, f)
               : run_slab<NeoHookeanPack, WithEnergy::no>(b, b.neo_hookean_packs, slab, x, f);
  return with_energy ? run_slab<LinearPack, WithEnergy::yes>(b, b.linear_packs, slab, x, f)
                     : run_slab<LinearPack, WithEnergy::no>(b, b.linear_packs, slab, x, f);
}

// Appends the packs of one slab's elements to its block, with their lane-to-element map.
void add_slab(ElementSet& es, int block, std::span<const int> elements) {
  ElementBlock& b = es.blocks[static_cast<size_t>(block)];
  Slab slab;
  slab.block = block;
  const int count = static_cast<int>(elements.size());
  slab.n_packs = (count + kLanes - 1) / kLanes;
  slab.last_lanes = count - (slab.n_packs - 1) * kLanes;
  if (b.model == MaterialModel::neo_hookean) {
    slab.first_pack = static_cast<int>(b.neo_hookean_packs.size());
    auto packs = make_element_packs<NeoHookeanPack>(es.tets, es.reference, elements);
    b.neo_hookean_packs.insert(b.neo_hookean_packs.end(), packs.begin(), packs.end());
  } else {
    slab.first_pack = static_cast<int>(b.linear_packs.size());
    auto packs = make_element_packs<LinearPack>(es.tets, es.reference, elements);
    b.linear_packs.insert(b.linear_packs.end(), packs.begin(), packs.end());
  }
  for (int i = 0; i < slab.n_packs * kLanes; ++i)
    b.lane_element.push_back(elements[static_cast<size_t>(std::min(i, count - 1))]);
  es.schedule.slabs.push_back(slab);
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
  std::vector<BlockSlabs> cuts;
  for (const Body& body : mesh.bodies) {
    // A rigid body keeps a block (blocks are per body) without slabs: the step never sees it.
    es.blocks.push_back({body.first_element,
                         body.n_elements,
                         body.material.model,
                         lame_from(body.material),
                         body.rigid ? 0.0 : dilatational_wave_speed(body.material),
                         {},
                         {},
                         {},
                         body.element,
                         body.first_node,
                         body.n_nodes});
    cuts.push_back(
        cut_into_slabs(mesh.X, mesh.tets, body.first_element, body.rigid ? 0 : body.n_elements));
  }
  std::vector<std::span<const int>> slab_elements;
  for (size_t b = 0; b < cuts.size(); ++b)
    for (size_t k = 0; k + 1 < cuts[b].begin.size(); ++k) {
      const std::span<const int> all(cuts[b].elements);
      const auto span = all.subspan(static_cast<size_t>(cuts[b].begin[k]),
                                    static_cast<size_t>(cuts[b].begin[k + 1] - cuts[b].begin[k]));
      if (span.empty()) continue;
      add_slab(es, static_cast<int>(b), span);
      slab_elements.push_back(span);
    }
  es.schedule.phases = make_phases(mesh.n_nodes(), es.tets, es.schedule.slabs, slab_elements);
  prepare_nodal_pressure(es, mesh);
  return es;
}

namespace {

// Without a clock: nothing timed.
struct NoClock {
  void start() {}
  void busy_until_now() {}
  void wait_until_now() {}
};

// The calling thread's share of a SlabClock (omp_get_thread_num: 0 outside a region).
class ThreadClock {
 public:
  explicit ThreadClock(SlabClock& clock) : mine_(clock.threads[omp_get_thread_num()]) {}
  void start() { last_ = now(); }
  void busy_until_now() { mine_.busy += lap(); }
  void wait_until_now() { mine_.wait += lap(); }

 private:
  static double now() { return omp_get_wtime(); }
  double lap() {
    const double t = now(), d = t - last_;
    last_ = t;
    return d;
  }
  SlabClock::PerThread& mine_;
  double last_ = 0.0;
};

// The nodal passes and every phase's slabs, in order; inside a parallel region each `omp for`
// shares a phase's slabs among the team (the barrier after it ends the phase), outside one the
// calling thread runs them all.
template <class Clock>
void evaluate_phases(const ElementSet& elements, const PaddedVec3* xp, PaddedVec3* fp,
                     bool with_energy, std::vector<SlabTotals>& totals, Clock&& clock) {
  const ElementSchedule& schedule = elements.schedule;
  update_nodal_pressures(elements, xp);
  for (const std::vector<int>& phase : schedule.phases) {
    clock.start();
    // Static: each thread takes the same contiguous run of a phase's slabs at every step, so
    // the nodal forces it writes stay in its own core's cache (a dynamic assignment moved them
    // between the cores at every step: docs/parallel.md, "The slow mode").
#pragma omp for schedule(static) nowait
    for (size_t k = 0; k < phase.size(); ++k) {
      const auto s = static_cast<size_t>(phase[k]);
      const Slab& slab = schedule.slabs[s];
      totals[s] = run_slab(elements, elements.blocks[static_cast<size_t>(slab.block)], slab, xp, fp,
                           with_energy);
    }
    clock.busy_until_now();
#pragma omp barrier
    clock.wait_until_now();
  }
}

// The evaluation's phases on `threads` threads: one thread enters no region, outside which the
// `omp for`s run in order and the barriers return at once (a region of one thread would still
// wake a futex at each: engine/threads/index_loop.hpp). With a clock, each thread times its own.
void run_phases(const ElementSet& elements, const PaddedVec3* xp, PaddedVec3* fp, bool with_energy,
                std::vector<SlabTotals>& totals, int threads, SlabClock* clock) {
  if (clock) clock->threads.resize(std::max<size_t>(clock->threads.size(), threads));
  if (threads <= 1) {
    if (clock) return evaluate_phases(elements, xp, fp, with_energy, totals, ThreadClock(*clock));
    return evaluate_phases(elements, xp, fp, with_energy, totals, NoClock{});
  }
#pragma omp parallel num_threads(threads)
  {
    if (clock)
      evaluate_phases(elements, xp, fp, with_energy, totals, ThreadClock(*clock));
    else
      evaluate_phases(elements, xp, fp, with_energy, totals, NoClock{});
  }
}

InternalForceResult evaluate(const ElementSet& elements, std::span<const PaddedVec3> x,
                             std::span<PaddedVec3> f, std::span<double> block_energy, int threads,
                             SlabClock* clock);

}  // namespace

InternalForceResult add_internal_forces(const ElementSet& elements, std::span<const Vec3> x,
                                        std::span<Vec3> f, std::span<double> block_energy,
                                        int threads) {
  PaddedNodes x4(x.size()), f4(f.size());
  for (size_t i = 0; i < x.size(); ++i) x4[i] = padded(x[i]);
  const InternalForceResult r = add_internal_forces(elements, x4, f4, block_energy, threads);
  for (size_t i = 0; i < f.size(); ++i) f[i] += unpadded(f4[i]);
  return r;
}

InternalForceResult add_internal_forces(const ElementSet& elements, std::span<const PaddedVec3> x,
                                        std::span<PaddedVec3> f, std::span<double> block_energy,
                                        int threads) {
  return evaluate(elements, x, f, block_energy, threads, nullptr);
}

InternalForceResult add_internal_forces(const ElementSet& elements, std::span<const PaddedVec3> x,
                                        std::span<PaddedVec3> f, std::span<double> block_energy,
                                        int threads, SlabClock& clock) {
  return evaluate(elements, x, f, block_energy, threads, &clock);
}

namespace {

InternalForceResult evaluate(const ElementSet& elements, std::span<const PaddedVec3> x,
                             std::span<PaddedVec3> f, std::span<double> block_energy, int threads,
                             SlabClock* clock) {
  const PaddedVec3* xp = x.data();
  PaddedVec3* fp = f.data();
  const bool with_energy = !block_energy.empty();
  threads = std::max(1, threads);
  const ElementSchedule& schedule = elements.schedule;
  std::vector<SlabTotals> totals(schedule.slabs.size());
  // One parallel region for the whole evaluation: the nodal passes of the nodal-pressure blocks
  // (nodal_pressure.hpp; none: nothing), then the slabs. The slabs of one phase share no node;
  // the barrier at the end of each phase keeps the phases in order (element_schedule.hpp).
  run_phases(elements, xp, fp, with_energy, totals, threads, clock);
  // Fixed-order combination: slab order, whatever thread ran which slab.
  if (with_energy) std::fill(block_energy.begin(), block_energy.end(), 0.0);
  InternalForceResult r;
  double min_ratio2 = std::numeric_limits<double>::infinity();  // min_e (h_e / c_d,e)^2
  for (size_t s = 0; s < schedule.slabs.size(); ++s) {
    const SlabTotals& t = totals[s];
    const ElementBlock& b = elements.blocks[static_cast<size_t>(schedule.slabs[s].block)];
    // y = rho / dt_e^2 with rho = (lambda + 2 mu) / c_d^2.
    const double c2 = b.wave_speed * b.wave_speed;
    min_ratio2 = std::min(min_ratio2, (b.lame.lambda + 2.0 * b.lame.mu) / (c2 * t.max_y));
    r.min_J = std::min(r.min_J, t.min_J);
    if (t.first_bad >= 0 && (r.first_bad_element < 0 || t.first_bad < r.first_bad_element)) {
      r.first_bad_element = t.first_bad;
      r.bad_J = t.bad_J;
    }
    if (with_energy) block_energy[static_cast<size_t>(schedule.slabs[s].block)] += t.energy;
  }
  if (with_energy) add_nodal_volumetric_energy(elements, block_energy);
  r.stable_dt = std::sqrt(min_ratio2);
  return r;
}

}  // namespace

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
