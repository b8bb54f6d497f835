#include "tests/support/refined_sphere.hpp"

#include <unistd.h>

#include <filesystem>
#include <string>

#include "engine/mesh/gmsh_api.hpp"
#include "engine/mesh/gmsh_mesher.hpp"

namespace ccm::test {
namespace {

// Box field: h_min inside the box around the +z pole, growing to h_max over `transition`.
void set_pole_refinement(const RefinedSphere& s) {
  namespace field = gmsh::model::mesh::field;
  const int box = field::add("Box");
  field::setNumber(box, "VIn", s.h_min);
  field::setNumber(box, "VOut", s.h_max);
  field::setNumber(box, "XMin", -s.refined_radius);
  field::setNumber(box, "XMax", s.refined_radius);
  field::setNumber(box, "YMin", -s.refined_radius);
  field::setNumber(box, "YMax", s.refined_radius);
  field::setNumber(box, "ZMin", s.radius - s.refined_radius);
  field::setNumber(box, "ZMax", 2 * s.radius);
  field::setNumber(box, "Thickness", s.transition);
  field::setAsBackgroundMesh(box);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMin", s.h_min);
  gmsh::option::setNumber("Mesh.MeshSizeMax", s.h_max);
  gmsh::option::setNumber("Mesh.Algorithm3D", 1);  // Delaunay: deterministic
  gmsh::option::setNumber("Mesh.Optimize", 1);
}

// Writes the mesh of the sphere (refined pole at +z, centred at the origin) to `path`.
void write_refined_sphere(const RefinedSphere& s, const std::string& path) {
  gmsh::initialize(0, nullptr, false);
  try {
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.NumThreads", 1);
    gmsh::model::add("refined_sphere");
    gmsh::model::occ::addSphere(0, 0, 0, s.radius);
    gmsh::model::occ::synchronize();
    set_pole_refinement(s);
    gmsh::model::mesh::generate(3);
    gmsh::write(path);
  } catch (...) {
    gmsh::finalize();
    throw;
  }
  gmsh::finalize();
}

}  // namespace

TetMesh refined_sphere(const RefinedSphere& spec, const Vec3& centre, int pole_sign) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("ccm_refined_sphere_" + std::to_string(::getpid()) + ".msh");
  write_refined_sphere(spec, path.string());
  TetMesh mesh = read_msh_file(path);
  std::filesystem::remove(path);
  for (Vec3& x : mesh.nodes) {
    if (pole_sign < 0) x = Vec3(x.x(), -x.y(), -x.z());  // half turn about x: keeps orientation
    x += centre;
  }
  return mesh;
}

}  // namespace ccm::test
