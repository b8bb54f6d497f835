// How many threads one run uses (docs/parallel.md, "Threads (OpenMP)"). A run's result does not
// depend on it; only its speed does.
#pragma once

#include <optional>

namespace ccm {

// The cores this process may run on (its CPU affinity), at least 1.
int available_cores();

// The thread count runs use when RunOptions::threads is 0: 1 until set (the command line sets
// it from --threads, CCM_THREADS or the cores available).
int default_threads();
void set_default_threads(int threads);

// CCM_THREADS when set: its value, a positive integer; std::invalid_argument naming the
// variable and the value otherwise. Empty when unset or empty.
std::optional<int> threads_from_environment();

}  // namespace ccm
