// The averaged-nodal-pressure tet (Bonet & Burton 1998; docs/elements.md, eq. NP.1-NP.6): the
// compressible Neo-Hookean energy split into the part each element keeps,
//   W_e = mu/2 (tr C - 3) - mu ln J_e,
// and the volumetric part U(J) = lambda/2 (ln J)^2, evaluated at the nodes on the nodal
// Jacobian J_n = V_n / V0_n, so a mesh of linear tets no longer locks as nu -> 0.5. The forces
// are the exact gradient of sum_e V0_e W_e + sum_n V0_n U(J_n), so the energy balance holds as
// for the plain tet. One evaluation is three passes:
//   1. element volumes scattered to the nodes (the slab/phase schedule: fixed order),
//   2. nodal pressures p_n = U'(J_n) (a node loop),
//   3. element forces with the element's mean nodal pressure (run_nodal_pressure_slab).
// add_internal_forces (internal_force.hpp) runs all three in its one parallel region.
#pragma once

#include <span>

#include "engine/element/internal_force.hpp"
#include "engine/element/slab_totals.hpp"
#include "engine/mesh/model_mesh.hpp"

namespace ccm {

// The reference nodal volumes V0_n of the blocks of element nodal_pressure (eq. NP.1) and the
// scratch sized; nothing when no block uses it. Throws std::runtime_error naming the body when
// such a block's material is not Neo-Hookean.
void prepare_nodal_pressure(ElementSet& elements, const ModelMesh& mesh);

// Passes 1 and 2: V_n, then the rows (x, y, z, p_n) and each block's largest |ln J_n| into
// elements.nodal (bitwise the same for any thread count). Called by every thread of the force
// loop's parallel region (its loops are orphaned `omp for`s; outside a region, one thread runs
// them all), so the nodal passes add no fork-join of their own; ends with a barrier, after which
// pass 3 may read every row. Does nothing when no block uses the element.
void update_nodal_pressures(const ElementSet& elements, const PaddedVec3* x);

// Pass 3 for one slab of a nodal-pressure block: adds the forces into f and reports the slab as
// the plain kernel does; energy (with_energy) is the elements' part sum_e V0_e W_e only. Reads the
// positions and pressures update_nodal_pressures stored (elements.nodal.position_pressure).
SlabTotals run_nodal_pressure_slab(const ElementSet& elements, const ElementBlock& block,
                                   const Slab& slab, PaddedVec3* f, bool with_energy);

// Adds the nodal volumetric energy sum_n V0_n U(J_n) of every nodal-pressure block to its entry
// of block_energy (node order: fixed). Reads the V_n of the last update_nodal_pressures.
void add_nodal_volumetric_energy(const ElementSet& elements, std::span<double> block_energy);

}  // namespace ccm
