#include "engine/contact/dcr/thread_chunks.hpp"

#include <exception>

#include "engine/threads/thread_count.hpp"

namespace ccm::dcr {

const ChunkedLoops& serial_loops() {
  static const ChunkedLoops serial;  // threads() is 1 until resolve_threads(), never called
  return serial;
}

void ChunkedLoops::resolve_threads() {
  threads_ = use_.threads > 0 ? use_.threads : default_threads();
}

int ChunkedLoops::chunks(std::size_t n, std::size_t item_weight) const {
  const int c = kChunksPerThread * threads_;
  if (threads_ <= 1 || n * item_weight < use_.min_items || n < static_cast<std::size_t>(c))
    return 1;
  return c;
}

void ChunkedLoops::run(std::size_t n,
                       const std::function<void(std::size_t, std::size_t, int)>& body,
                       std::size_t item_weight) const {
  const int c_total = chunks(n, item_weight);
  if (c_total == 1) {
    body(0, n, 0);
    return;
  }
  ++threaded_loops_;
  failed_.assign(static_cast<std::size_t>(c_total), nullptr);
  // One chunk per iteration: every chunk runs even if OpenMP grants fewer threads than asked.
#pragma omp parallel for num_threads(threads_) schedule(dynamic, 1)
  for (int c = 0; c < c_total; ++c) {
    const std::size_t begin = n * static_cast<std::size_t>(c) / static_cast<std::size_t>(c_total);
    const std::size_t end = n * static_cast<std::size_t>(c + 1) / static_cast<std::size_t>(c_total);
    try {
      body(begin, end, c);
    } catch (...) {  // an exception may not leave the parallel region
      failed_[static_cast<std::size_t>(c)] = std::current_exception();
    }
  }
  for (const std::exception_ptr& e : failed_)
    if (e) std::rethrow_exception(e);
}

}  // namespace ccm::dcr
