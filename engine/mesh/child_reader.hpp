// Reading a mesh in a child process, with a deadline. Gmsh's own file reader crashes on some
// malformed files (a segmentation fault inside GModel, found by the fuzz_msh_mesh target): in a
// child, a crash becomes a MeshError naming the file instead of ending ccm. A child that has not
// answered by the deadline is killed and the read tried once more (a child forked from a
// multi-threaded process can inherit a lock another thread held, and then never finishes: seen
// once in the fuzz smoke, a 64 ms input that stopped for 10 s); a second miss is a MeshError.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>

#include "engine/mesh/tet_mesh.hpp"

namespace ccm {

struct ChildReadSettings {
  std::chrono::milliseconds deadline;  // per attempt
  std::mutex* fork_lock = nullptr;     // held across fork(), so that no thread holds it then
};

// How long a reader of a file of `bytes` bytes may take: 5 s and 1 s per MB (Gmsh reads ASCII
// meshes at tens of MB/s, under the sanitizers too).
std::chrono::milliseconds reader_deadline(std::uintmax_t bytes);

// Runs `read` in a child process and returns its mesh (passed back in the mesh cache's byte
// format). A MeshError in the child is rethrown as one, another exception as std::runtime_error,
// both with the child's message; a crash, or a second missed deadline, is a MeshError naming
// `where`.
TetMesh read_in_child(const std::string& where, const ChildReadSettings& settings,
                      const std::function<TetMesh()>& read);

}  // namespace ccm
