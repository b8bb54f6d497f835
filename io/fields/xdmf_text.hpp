// The XDMF 3 half of the field files (docs/fields.md): a temporal collection with one frame
// per output time; each frame a spatial collection of the grid "bodies" (every tet of every
// body) and, when contact pressure is written, the grid "surfaces" (every boundary triangle).
// The mesh is stored once in the HDF5 file and referenced by every frame; its geometry is the
// reference configuration (ParaView: Warp By Vector with `displacement` shows the deformed one).
#pragma once

#include <string>
#include <vector>

#include "engine/observe/field_catalog.hpp"

namespace ccm::fields {

// Dataset paths of the HDF5 file.
inline constexpr const char* kNodesDataset = "/mesh/nodes";           // n_nodes x 3, m
inline constexpr const char* kTetsDataset = "/mesh/tets";             // n_tets x 4, node ids
inline constexpr const char* kFacesDataset = "/mesh/faces";           // n_faces x 3, node ids
inline constexpr const char* kBodyIdDataset = "/mesh/body_id";        // n_tets
inline constexpr const char* kFaceBodyIdDataset = "/mesh/face_body";  // n_faces
inline constexpr const char* kTimeDataset = "/time";                  // n_frames, s

// "/frames/000012/von_mises": the values of one field at frame k (not for body_id: it does not
// change and is stored once under /mesh).
std::string frame_dataset(int frame, FieldKind kind);

struct XdmfLayout {
  std::string h5_name;  // the HDF5 file, relative to the .xdmf (same folder)
  long n_nodes = 0, n_tets = 0, n_faces = 0;
  std::vector<FieldKind> fields;
  std::vector<double> times;  // frame k is at times[k] [s]
  std::string title;          // free text, written into an Information element
};

// The grid "surfaces" is written when contact_pressure is among the fields.
bool has_surface_grid(const std::vector<FieldKind>& fields);

std::string xdmf_text(const XdmfLayout& layout);

}  // namespace ccm::fields
