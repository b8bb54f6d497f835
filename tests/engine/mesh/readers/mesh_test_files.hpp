// Helpers the mesh reader tests share: the real mesh files in tests/data/meshes (see SOURCES.md
// there), surface area and normal sums, truncated and edited copies of a file.
#pragma once

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "engine/mesh/gmsh_mesher.hpp"  // MeshError
#include "engine/mesh/tet_mesh.hpp"
#include "tests/support/temp_dir.hpp"

namespace ccm::test {

inline std::filesystem::path mesh_data(const std::string& name) {
  return std::filesystem::path(CCM_SOURCE_DIR) / "tests" / "data" / "meshes" / name;
}

inline std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Sum over the triangles of their area vectors (x1 - x0) x (x2 - x0) / 2: for a flat surface its
// norm is the area and its direction the (outward) normal.
inline Vec3 area_vector(const TetMesh& mesh, const std::vector<Triangle>& triangles) {
  Vec3 sum = Vec3::Zero();
  for (const Triangle& t : triangles) {
    const Vec3& x0 = mesh.nodes[static_cast<size_t>(t[0])];
    sum += 0.5 * (mesh.nodes[static_cast<size_t>(t[1])] - x0)
                     .cross(mesh.nodes[static_cast<size_t>(t[2])] - x0);
  }
  return sum;
}

// The volume a closed, outward-oriented triangle surface encloses (divergence theorem:
// V = sum over triangles of x0 . ((x1 - x0) x (x2 - x0)) / 6), independent of the tets.
inline double enclosed_volume(const TetMesh& mesh, const std::vector<Triangle>& triangles) {
  double v = 0;
  for (const Triangle& t : triangles) {
    const Vec3& x0 = mesh.nodes[static_cast<size_t>(t[0])];
    v += x0.dot((mesh.nodes[static_cast<size_t>(t[1])] - x0)
                    .cross(mesh.nodes[static_cast<size_t>(t[2])] - x0));
  }
  return v / 6.0;
}

// The message of the MeshError `read` throws, or "(no error)".
template <class Read>
std::string mesh_error_of(Read&& read) {
  try {
    read();
  } catch (const MeshError& e) {
    return e.what();
  }
  return "(no error)";
}

// Reads every prefix of `text` that ends at one of `cuts` (byte counts) as the file `name` in
// `dir`: each must either read or throw MeshError (no other exception, no crash); a message must
// name the file. Returns how many prefixes were refused.
template <class Read>
int read_truncated(const TempDir& dir, const std::string& name, const std::string& text,
                   const std::vector<size_t>& cuts, Read&& read) {
  int refused = 0;
  for (size_t cut : cuts) {
    const std::filesystem::path file = dir.write(name, text.substr(0, cut));
    try {
      read(file);
    } catch (const MeshError& e) {
      ++refused;
      const std::string what = e.what();
      INFO("cut at byte " << cut << ": " << what);
      CHECK(what.rfind(file.string() + ":", 0) == 0);
    }
  }
  return refused;
}

// Byte offsets just after every line break of `text`, and `extra` more spread over the bytes.
inline std::vector<size_t> cut_points(const std::string& text, size_t every_nth_line,
                                      size_t extra) {
  std::vector<size_t> cuts;
  size_t line = 0;
  for (size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n' && line++ % every_nth_line == 0) cuts.push_back(i + 1);
  for (size_t k = 1; k <= extra; ++k) cuts.push_back(k * text.size() / (extra + 1) + k % 7);
  return cuts;
}

}  // namespace ccm::test
