// Internal nodal forces of all tets, with the per-element stable time step of the current
// configuration and, on request, the stored strain energy.
#pragma once

#include <limits>
#include <span>
#include <vector>

#include "engine/core/element_kind.hpp"
#include "engine/element/element_pack.hpp"
#include "engine/element/element_schedule.hpp"
#include "engine/element/nodal_pressure_data.hpp"
#include "engine/element/padded_nodes.hpp"
#include "engine/element/tet4.hpp"
#include "engine/material/material.hpp"
#include "engine/mesh/model_mesh.hpp"

namespace ccm {

// A contiguous range of elements with one material (one body).
struct ElementBlock {
  int first = 0;
  int count = 0;
  MaterialModel model = MaterialModel::neo_hookean;
  Lame lame{};
  double wave_speed = 0.0;  // dilatational c_d of the material
  // The block's elements as the kernel reads them, slab after slab (element_schedule.hpp): one
  // of the two, by the model.
  std::vector<NeoHookeanPack> neo_hookean_packs;
  std::vector<LinearPack> linear_packs;
  std::vector<int> lane_element;  // the global element of every pack lane (padding repeats)
  ElementKind element = kDefaultElementKind;  // nodal_pressure: see nodal_pressure.hpp
  int first_node = 0;                         // the body's nodes [first_node, first_node + n_nodes)
  int n_nodes = 0;
};

struct ElementSet {
  std::vector<Tet> tets;
  std::vector<TetReference> reference;
  std::vector<ElementBlock> blocks;
  ElementSchedule schedule;
  NodalPressureData nodal;  // for the blocks of element nodal_pressure
  int n_elements() const { return static_cast<int>(tets.size()); }
};

// Throws std::runtime_error naming the element when a reference tet has no positive volume, or
// the body when it asks for the nodal-pressure element with a material other than Neo-Hookean.
ElementSet make_element_set(const ModelMesh& mesh);

struct InternalForceResult {
  double stable_dt = std::numeric_limits<double>::infinity();  // min_e h_e / c_d,e (no safety)
  double min_J = std::numeric_limits<double>::infinity();
  int first_bad_element = -1;  // lowest-numbered element with J <= 0 or non-finite J, else -1
  double bad_J = 0.0;          // its J
};

// f_int is ADDED into f as the force ON the nodes (f_a = -V0 P grad N_a); x is the current
// configuration. Reads each tet once: F, P, forces and stable step. When block_energy is not
// empty (one entry per block) the stored energy sum_e V0 W(F_e) of each block is written there;
// otherwise it is not computed. Up to `threads` OpenMP threads share the slabs of each phase of
// elements.schedule; every result is bitwise the same for any thread count.
InternalForceResult add_internal_forces(const ElementSet& elements, std::span<const Vec3> x,
                                        std::span<Vec3> f, std::span<double> block_energy = {},
                                        int threads = 1);

// The same on padded nodes (padded_nodes.hpp), the form the kernel moves without repacking: the
// integrator's path. f is added into as above; its fourth components stay as they are.
InternalForceResult add_internal_forces(const ElementSet& elements, std::span<const PaddedVec3> x,
                                        std::span<PaddedVec3> f,
                                        std::span<double> block_energy = {}, int threads = 1);

// Where each thread's time went in evaluations of the padded overload below, for benchmarks
// (bench_element_step; a run passes none): per thread, the seconds it spent running its slabs
// (busy) and waiting at the barrier that ends each phase for the other threads (wait), summed over
// the calls. The nodal-pressure passes before the phases are in neither.
struct SlabClock {
  struct alignas(64) PerThread {  // a cache line each: every thread writes its own at every slab
    double busy = 0.0, wait = 0.0;
  };
  std::vector<PerThread> threads;  // sized to the thread count by the first evaluation
};

// The padded evaluation, timed per thread into `clock` (the same forces and results, bit for bit).
InternalForceResult add_internal_forces(const ElementSet& elements, std::span<const PaddedVec3> x,
                                        std::span<PaddedVec3> f, std::span<double> block_energy,
                                        int threads, SlabClock& clock);

// Reference-configuration stable step min_e h_e / c_d,e, used before the first evaluation.
double reference_stable_dt(const ElementSet& elements, std::span<const Vec3> X);

}  // namespace ccm
