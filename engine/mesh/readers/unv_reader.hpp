// I-DEAS universal files (.unv), as Salome, NX/I-DEAS, FEMAP and ElmerGrid write them (ASCII).
//
// Read: dataset 164 (units: coordinates are converted to metres with its length factor), 2411
// (nodes), 2412 (elements: linear tetrahedra, FE descriptor 111; linear triangles 41, 51, 61, 74,
// 81, 91 are kept for groups; beams, rods, quadrilaterals and other shells are ignored and
// counted), and 2467 / 2477 / 2435 (groups). A group's triangles become a named surface, its
// nodes and the nodes of its tetrahedra a named node set of the same name. Other datasets are
// skipped. Written without Gmsh because Gmsh 4.8 drops the groups.
#pragma once

#include <filesystem>

#include "engine/mesh/readers/mesh_file_report.hpp"

namespace ccm {

// Throws MeshError "<file>:<line>: dataset <n> (<what>): <problem>" for anything malformed or
// truncated, for a volume element that is not a linear tetrahedron (wedges, bricks, quadratic
// tets), and for a binary dataset.
MeshFile read_unv_file(const std::filesystem::path& path);

}  // namespace ccm
