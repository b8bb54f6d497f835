// Abaqus / CalculiX input files (.inp): the mesh part of the deck.
//
// Read (keywords and parameter names case-insensitive, `**` comment lines, keyword lines continued
// after a final comma): *NODE (NSET=), *ELEMENT TYPE=C3D4 or C3D4H (ELSET=), *NSET and *ELSET
// (GENERATE, set names among the labels, *NSET ELSET=), *SURFACE TYPE=ELEMENT (element or
// element set with face S1..S4 of the C3D4, or no face for all free faces of the set) and
// TYPE=NODE, *INCLUDE INPUT= (relative to the including file). Everything from *STEP to
// *END STEP and every other keyword (materials, sections, boundary conditions) is skipped.
//
// Named results: every *NSET a node set; every *ELSET a node set of its tets' nodes (3-node
// triangle elements in it, e.g. S3 or CPS3 on the solid's faces, make it a named surface);
// every *SURFACE TYPE=ELEMENT a named surface, TYPE=NODE a node set. Set names keep the spelling
// of their first definition and are matched case-insensitively, as Abaqus does.
#pragma once

#include <filesystem>

#include "engine/mesh/readers/mesh_file_report.hpp"

namespace ccm {

// Throws MeshError "<file>:<line>: *<KEYWORD>: <problem>" for anything malformed, for solid
// elements other than C3D4 (C3D10, C3D8, ...), for part instances with a placement, several
// parts, nodes in a non-rectangular system, and for a reference to an undefined set, node or
// element.
MeshFile read_inp_file(const std::filesystem::path& path);

}  // namespace ccm
