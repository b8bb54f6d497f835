#include "engine/threads/thread_count.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace ccm {
namespace {
std::atomic<int> g_default_threads{1};
}  // namespace

int available_cores() { return std::max(1, omp_get_num_procs()); }

int default_threads() { return g_default_threads.load(); }

void set_default_threads(int threads) { g_default_threads.store(std::max(1, threads)); }

std::optional<int> threads_from_environment() {
  const char* value = std::getenv("CCM_THREADS");
  if (!value || !*value) return std::nullopt;
  const std::string text(value);
  std::size_t used = 0;
  int n = 0;
  try {
    n = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || n < 1)
    throw std::invalid_argument(
        fmt::format("environment variable CCM_THREADS: '{}' is not a positive integer", text));
  return n;
}

}  // namespace ccm
