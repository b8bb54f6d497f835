// Linear-tetrahedron meshes from Gmsh: meshed primitives (OpenCASCADE kernel) and .msh files.
//
// Every call initializes Gmsh, does its work and finalizes it again, under a process-wide mutex
// (Gmsh is a global singleton and not thread-safe: nothing else may use Gmsh meanwhile). Gmsh
// never sees argv or the user's configuration files, and prints nothing: all problems surface as
// MeshError.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "engine/core/types.hpp"
#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Rigid placement of a primitive: rotate about the origin first, then translate.
struct Placement {
  Vec3 translation = Vec3::Zero();
  Vec3 rotation_axis = Vec3::UnitZ();  // need not be normalized; must be non-zero
  double rotation_deg = 0.0;
};

enum class PrimitiveKind { sphere, box, cylinder, pipe };

// A finer mesh in a ball (local coordinates of the primitive, before placement): tet edges of
// mesh_size inside the ball, growing linearly to the primitive's mesh_size over a shell of one
// more radius outside it (Gmsh's "Ball" size field). Where two bodies touch, the contact zone
// needs the fine mesh and the rest of the body does not.
struct LocalRefinement {
  Vec3 center = Vec3::Zero();
  double radius = 0;      // > 0
  double mesh_size = 0;   // > 0, at most the primitive's mesh_size
  double transition = 0;  // width over which the size grows to the primitive's; 0: `radius`
};

struct PrimitiveSpec {
  PrimitiveKind kind;
  double radius = 0;         // sphere, cylinder; pipe: outer radius
  double inner_radius = 0;   // pipe only
  double length = 0;         // cylinder/pipe: along local +z, base at local origin
  Vec3 size = Vec3::Zero();  // box: extents, corner at local origin (box spans [0,size])
  bool centered = false;     // box/cylinder/pipe: centre the shape on the local origin instead
                             // (a sphere is always centred on the origin)
  double mesh_size = 0;      // characteristic length (Mesh.MeshSizeMin/Max)
  std::optional<LocalRefinement> refinement = std::nullopt;
};

// Meshes the primitive with 3D Delaunay (deterministic: the same spec gives the same mesh) and
// places it. Nodes are numbered 0..n-1 in Gmsh tag order and all belong to some tet; tets have
// positive volume, ordered by Gmsh tag. named_surfaces stays empty. Throws MeshError when a field
// is out of range (the message names the field), when mesh_size exceeds the radius of a curved
// face (radius; inner_radius for a pipe) or would give more than about 5e6 tets, or when Gmsh
// fails.
TetMesh mesh_primitive(const PrimitiveSpec& spec, const Placement& placement);

// Reads the linear tets (element type 4) of a Gmsh MSH file (format 2 or 4, ASCII or binary),
// with the same numbering and orientation guarantees as mesh_primitive. Every named physical group
// of dimension 2 becomes a named surface of triangles oriented out of the tet each one bounds, and
// every named physical group of dimension 3 a region (see mesh_gmsh_model).
// Throws MeshError, naming the path, if the file is missing, unreadable, does not start with
// "$MeshFormat", holds no linear tets, or has a named triangle that is not a face of any tet.
// Never executes scripts: not the file (Gmsh would parse a non-MSH file as a .geo script) nor a
// "<path>.opt" beside it (which Gmsh would otherwise run).
TetMesh read_msh_file(const std::filesystem::path& path);

// Meshes a model the caller builds: `build` runs inside the same Gmsh session as the functions
// above (the process-wide lock; Gmsh initialized without argv or configuration files) and must
// leave a generated 3D mesh in the current model (OpenCASCADE booleans, mesh sizes, physical
// groups and gmsh::model::mesh::generate(3) are its business). Returns its linear tets with the
// guarantees of mesh_primitive; every named physical group of dimension 2 becomes a named
// surface (as in read_msh_file) and every named physical group of dimension 3 a region, each tet
// then belonging to exactly one region. Throws MeshError prefixed with `context` when Gmsh fails,
// no tet was generated, or, when regions are named, a tet is in none or in two of them.
TetMesh mesh_gmsh_model(const std::string& context, const std::function<void()>& build);

}  // namespace ccm
