// A sum over n terms shared by threads whose result does not depend on their number: the terms
// are added in chunks of kSumChunk consecutive indices, each chunk in index order, and the chunk
// sums in chunk order. Only for .cpp files compiled with OpenMP (the engine's).
#pragma once

#include <algorithm>
#include <vector>

#include "engine/threads/index_loop.hpp"

namespace ccm {

inline constexpr int kSumChunk = 4096;

template <class Term>
double fixed_order_sum(int n, int threads, Term term) {
  const int chunks = (n + kSumChunk - 1) / kSumChunk;
  std::vector<double> partial(static_cast<size_t>(chunks), 0.0);
  for_each_index(static_cast<size_t>(chunks), threads, threads > 1 && chunks > 1, [&](size_t k) {
    const int c = static_cast<int>(k);
    const int end = std::min(n, (c + 1) * kSumChunk);
    double s = 0.0;
    for (int i = c * kSumChunk; i < end; ++i) s += term(i);
    partial[k] = s;
  });
  double total = 0.0;
  for (double p : partial) total += p;
  return total;
}

}  // namespace ccm
