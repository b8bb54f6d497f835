#include "engine/mesh/mesh_cache.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <sstream>
#include <system_error>
#include <vector>

namespace ccm {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr std::string_view kMagic = "CCMMESH1\n";

std::mutex& state_mutex() {
  static std::mutex m;
  return m;
}

MeshCacheSettings& settings_storage() {
  static MeshCacheSettings s = [] {
    MeshCacheSettings d;
    const char* env = std::getenv("CCM_MESH_CACHE");
    if (env && std::string_view(env) == "off") d.enabled = false;
    return d;
  }();
  return s;
}

MeshCacheStats& stats_storage() {  // per thread: runs side by side count apart (header)
  thread_local MeshCacheStats s;
  return s;
}

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// ---- bytes ------------------------------------------------------------------------------------

template <typename T>
void put(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

void put_string(std::string& out, const std::string& s) {
  put<std::uint64_t>(out, s.size());
  out += s;
}

template <typename T, std::size_t N>
void put_arrays(std::string& out, const std::vector<std::array<T, N>>& v) {
  put<std::uint64_t>(out, v.size());
  for (const auto& a : v)
    for (const T& x : a) put(out, x);
}

struct Reader {
  std::string_view in;
  bool ok = true;

  template <typename T>
  T get() {
    T v{};
    if (in.size() < sizeof(T)) {
      ok = false;
      return v;
    }
    std::memcpy(&v, in.data(), sizeof(T));
    in.remove_prefix(sizeof(T));
    return v;
  }
  // A count of items of `item_bytes` each that the rest of the input can hold.
  std::size_t count(std::size_t item_bytes) {
    const auto n = get<std::uint64_t>();
    if (!ok || (item_bytes > 0 && n > in.size() / item_bytes)) ok = false;
    return ok ? static_cast<std::size_t>(n) : 0;
  }
  std::string string() {
    const std::size_t n = count(1);
    std::string s(in.substr(0, n));
    in.remove_prefix(n);
    return s;
  }
  template <typename T, std::size_t N>
  std::vector<std::array<T, N>> arrays() {
    std::vector<std::array<T, N>> v(count(N * sizeof(T)));
    for (auto& a : v)
      for (T& x : a) x = get<T>();
    return v;
  }
};

// ---- files ------------------------------------------------------------------------------------

fs::path folder() {
  const MeshCacheSettings s = mesh_cache_settings();
  return s.folder.empty() ? default_mesh_cache_folder() : s.folder;
}

fs::path file_of(const std::string& key) {
  return folder() / fmt::format("{:016x}.mesh", std::hash<std::string>{}(key));
}

bool read_file(const fs::path& file, const std::string& key, TetMesh& mesh) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  std::ostringstream all;
  all << in.rdbuf();
  const std::string text = all.str();
  Reader r{text};
  if (!text.starts_with(kMagic)) return false;
  r.in.remove_prefix(kMagic.size());
  if (r.string() != key || !r.ok) return false;  // another key under the same hash: a miss
  const std::uint64_t sum = r.get<std::uint64_t>();
  if (!r.ok || sum != std::hash<std::string_view>{}(r.in)) return false;  // damaged
  return read_mesh_bytes(std::string(r.in), mesh);
}

// The least recently used files go until the folder is under 80 % of the bound.
void keep_under_bound(const fs::path& dir, std::uintmax_t max_bytes) {
  std::error_code ec;
  std::vector<std::pair<fs::file_time_type, fs::path>> files;
  std::uintmax_t total = 0;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (e.path().extension() != ".mesh") continue;
    total += e.file_size(ec);
    files.emplace_back(e.last_write_time(ec), e.path());
  }
  if (total <= max_bytes) return;
  std::sort(files.begin(), files.end());
  for (const auto& [time, path] : files) {
    if (total <= max_bytes / 5 * 4) break;
    const std::uintmax_t size = fs::file_size(path, ec);
    if (fs::remove(path, ec)) total -= size;
  }
}

void write_file(const fs::path& file, const std::string& key, const TetMesh& mesh) {
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  static std::atomic<long> serial{0};
  const fs::path tmp = file.string() + fmt::format(".tmp.{}.{}", getpid(), serial++);
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) return;  // a cache that cannot be written is no cache, not an error
    const std::string body = mesh_bytes(mesh);
    std::string head(kMagic);
    put_string(head, key);
    put<std::uint64_t>(head, std::hash<std::string_view>{}(body));
    out << head << body;
    if (!out) {
      fs::remove(tmp, ec);
      return;
    }
  }
  fs::rename(tmp, file, ec);
  if (ec) fs::remove(tmp, ec);
  keep_under_bound(file.parent_path(), mesh_cache_settings().max_bytes);
}

}  // namespace

fs::path default_mesh_cache_folder() {
  if (const char* env = std::getenv("CCM_MESH_CACHE");
      env && *env && std::string_view(env) != "off")
    return env;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return fs::path(xdg) / "ccm" / "meshes";
  if (const char* home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".cache" / "ccm" / "meshes";
  return fs::temp_directory_path() / "ccm-mesh-cache";
}

MeshCacheSettings mesh_cache_settings() {
  const std::lock_guard lock(state_mutex());
  return settings_storage();
}

void set_mesh_cache_settings(const MeshCacheSettings& settings) {
  const std::lock_guard lock(state_mutex());
  settings_storage() = settings;
}

MeshCacheStats mesh_cache_stats() { return stats_storage(); }

TetMesh cached_mesh(const std::string& key, const std::function<TetMesh()>& make) {
  const auto start = Clock::now();
  const bool enabled = mesh_cache_settings().enabled;
  const fs::path file = enabled ? file_of(key) : fs::path();
  TetMesh mesh;
  if (enabled && read_file(file, key, mesh)) {
    std::error_code ec;
    fs::last_write_time(file, fs::file_time_type::clock::now(), ec);  // recently used
    ++stats_storage().hits;
    stats_storage().read_seconds += seconds_since(start);
    return mesh;
  }
  mesh = make();
  if (enabled) write_file(file, key, mesh);
  ++stats_storage().misses;
  stats_storage().mesh_seconds += seconds_since(start);
  return mesh;
}

std::string mesh_bytes(const TetMesh& m) {
  std::string out;
  put<std::uint64_t>(out, m.nodes.size());
  for (const Vec3& x : m.nodes)
    for (int k = 0; k < 3; ++k) put<double>(out, x[k]);
  put_arrays(out, m.tets);
  put<std::uint64_t>(out, m.named_surfaces.size());
  for (const auto& [name, tris] : m.named_surfaces) {
    put_string(out, name);
    put_arrays(out, tris);
  }
  put<std::uint64_t>(out, m.named_node_sets.size());
  for (const auto& [name, nodes] : m.named_node_sets) {
    put_string(out, name);
    put<std::uint64_t>(out, nodes.size());
    for (int n : nodes) put<int>(out, n);
  }
  put<std::uint64_t>(out, m.region_names.size());
  for (const std::string& name : m.region_names) put_string(out, name);
  put<std::uint64_t>(out, m.tet_region.size());
  for (int r : m.tet_region) put<int>(out, r);
  return out;
}

bool read_mesh_bytes(const std::string& bytes, TetMesh& m) {
  Reader r{bytes};
  TetMesh out;
  out.nodes.resize(r.count(3 * sizeof(double)));
  for (Vec3& x : out.nodes)
    for (int k = 0; k < 3; ++k) x[k] = r.get<double>();
  out.tets = r.arrays<int, 4>();
  for (std::size_t s = r.count(2 * sizeof(std::uint64_t)); r.ok && s > 0; --s) {
    std::string name = r.string();
    out.named_surfaces[name] = r.arrays<int, 3>();
  }
  for (std::size_t s = r.count(2 * sizeof(std::uint64_t)); r.ok && s > 0; --s) {
    std::string name = r.string();
    std::vector<int>& nodes = out.named_node_sets[name];
    nodes.resize(r.count(sizeof(int)));
    for (int& n : nodes) n = r.get<int>();
  }
  out.region_names.resize(r.count(sizeof(std::uint64_t)));
  for (std::string& name : out.region_names) name = r.string();
  out.tet_region.resize(r.count(sizeof(int)));
  for (int& x : out.tet_region) x = r.get<int>();
  if (!r.ok || !r.in.empty()) return false;
  m = std::move(out);
  return true;
}

}  // namespace ccm
