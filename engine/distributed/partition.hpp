// METIS partition of a mesh's elements (docs/parallel.md "Distributed memory (METIS + MPI)"):
// the element dual graph (two tets are neighbours when they share a face), each element weighted
// by its cost, cut into parts of equal cost with the fewest cut faces.
#pragma once

#include <vector>

#include "engine/mesh/model_mesh.hpp"

namespace ccm::distributed {

// Relative cost of one element-step of a material model (measured, docs/parallel.md): the
// partition balances the sum of these, not the element count.
int element_cost(MaterialModel model);

// The part (0 .. n_parts-1) of every element. METIS balances the stepped elements; a rigid
// body's (never stepped, engine/body/) are given part 0, whose rank owns the body's nodes (every
// rank holds a replica of them, subdomain.hpp). n_parts == 1: all zero, no METIS call.
// Throws std::runtime_error when METIS fails.
std::vector<int> partition_elements(const ModelMesh& mesh, int n_parts);

struct PartitionQuality {
  std::vector<long> part_cost;  // sum of element_cost per part (a rigid body's: 0)
  double imbalance = 0.0;       // max part cost / mean part cost - 1
  long cut_faces = 0;           // faces shared by elements of two parts (the dual graph's edge cut)
};

PartitionQuality measure_partition(const ModelMesh& mesh, const std::vector<int>& part,
                                   int n_parts);

}  // namespace ccm::distributed
