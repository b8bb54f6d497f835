// The loops of the DCR contact's detection on OpenMP threads, with a result that does not depend
// on the thread count, to the bit (docs/parallel.md, "Threads").
//
// A loop over n items is cut into C contiguous chunks taken in item order, chunk c covering items
// [c n / C, (c + 1) n / C); C is kChunksPerThread x the thread count when the loop has enough
// work (ThreadUse::min_items), else 1. The threads take the chunks as they come free (a thread
// slowed by another process on its core then does fewer of them, and uneven items even out).
// Each chunk writes its own results (a list it appends to in item order, its own counters); the
// caller joins them in chunk order. Joined that way, a list is the serial loop's list whatever C
// is, provided an item's result depends on that item alone; minima, maxima, integer counts and
// logical ANDs do not depend on the order of their operands anyway. No floating-point sum is
// formed across items here (a sum would depend on where the chunks are cut).
//
// Only this file's .cpp is compiled with OpenMP: the loops hand it one call per chunk (a
// std::function call costs nothing against a chunk of thousands of items).
#pragma once

#include <cstddef>
#include <exception>
#include <functional>
#include <vector>

namespace ccm::dcr {

// Data that threads write often is kept this far apart (a cache line).
inline constexpr std::size_t kCacheLine = 64;

// How many threads the detection loops may use, and from what loop size.
struct ThreadUse {
  // Threads; 0: default_threads() (engine/threads/thread_count.hpp), read at each step.
  int threads = 0;
  // Loops of less work stay on one thread, counted in light items (a box, a few ns each); a
  // heavy item (a CCD test, a grid query: a hundred ns to a microsecond) counts kHeavyItem. A
  // parallel region costs microseconds on an idle machine and far more on a loaded one (a
  // thread that is not running holds up the region's end: 0.07-8 ms measured on the 2 shared
  // cores, docs/parallel.md).
  std::size_t min_items = 16384;
};

class ChunkedLoops {
 public:
  static constexpr int kChunksPerThread = 4;
  static constexpr std::size_t kHeavyItem = 16;  // weight of a heavy item (ThreadUse::min_items)

  explicit ChunkedLoops(ThreadUse use = {}) : use_(use) {}

  // The thread count of the loops until the next call (threads 0: default_threads()).
  void resolve_threads();
  int threads() const { return threads_; }

  // How many chunks a loop over n items of the given weight (1 light, kHeavyItem heavy) is cut
  // into (1: it runs on the calling thread).
  int chunks(std::size_t n, std::size_t item_weight = 1) const;

  // Calls body(begin, end, chunk) for every chunk of a loop over n items, the chunks on their own
  // threads. An exception thrown by a chunk is rethrown after the loop: the one of the lowest
  // chunk, which is the one the serial loop would have thrown first.
  void run(std::size_t n, const std::function<void(std::size_t, std::size_t, int)>& body,
           std::size_t item_weight = 1) const;

  // Loops that ran on more than one thread since construction (tests check that the threaded
  // paths were taken).
  long threaded_loops() const { return threaded_loops_; }

 private:
  ThreadUse use_;
  int threads_ = 1;
  mutable long threaded_loops_ = 0;
  mutable std::vector<std::exception_ptr> failed_;  // scratch of run(), per chunk
};

// Loops that always run on the calling thread (the default of the functions that take loops).
const ChunkedLoops& serial_loops();

// Per-chunk scratch lists, reused from one loop to the next. Each list's header sits on a cache
// line of its own: chunks on different threads append to their lists at every item, and headers
// sharing a line would bounce it between the cores at every append.
template <typename T>
class ChunkLists {
 public:
  // c empty lists (their storage kept).
  void reset(int c) {
    if (lists_.size() < static_cast<std::size_t>(c)) lists_.resize(static_cast<std::size_t>(c));
    for (int i = 0; i < c; ++i) lists_[static_cast<std::size_t>(i)].items.clear();
    used_ = c;
  }
  std::vector<T>& operator[](int c) { return lists_[static_cast<std::size_t>(c)].items; }
  // Appends the lists to out in chunk order.
  void append_to(std::vector<T>& out) const {
    for (int c = 0; c < used_; ++c) {
      const std::vector<T>& l = lists_[static_cast<std::size_t>(c)].items;
      out.insert(out.end(), l.begin(), l.end());
    }
  }

 private:
  struct alignas(kCacheLine) List {
    std::vector<T> items;
  };
  std::vector<List> lists_;
  int used_ = 0;
};

}  // namespace ccm::dcr
