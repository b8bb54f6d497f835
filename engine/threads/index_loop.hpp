// A loop over indices on OpenMP threads, or on the calling thread without entering OpenMP at all.
// Only for .cpp files compiled with OpenMP (engine/CMakeLists.txt lists them).
//
// Why not `#pragma omp parallel for if (parallel)`: with a false `if` clause libgomp still makes a
// team of one for the region, and its end wakes the team's barrier through a futex system call.
// On the rig's 3,105-tet model (one thread) that was about 5 system calls and a team set-up per
// step, a step of about 54 us (docs/parallel.md, "Regions a one-thread run never enters").
#pragma once

#include <cstddef>

namespace ccm {

// body(i) for every i in [0, n): on `threads` threads in contiguous static blocks when `parallel`,
// else in index order on the calling thread. Each i must be independent of the others.
//
// The calling thread's loop runs a copy of the body: the body's own object is passed to the OpenMP
// region below, so the compiler must assume that a store of the loop (x[i] = ...) may change its
// captures, and reloads them at every index; a local copy whose address does not escape stays in
// registers.
template <class Body>
void for_each_index(std::size_t n, int threads, bool parallel, Body&& body) {
  if (!parallel) {
    auto local = body;
    for (std::size_t i = 0; i < n; ++i) local(i);
    return;
  }
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::size_t i = 0; i < n; ++i) body(i);
}

}  // namespace ccm
