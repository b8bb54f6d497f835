// The round trip of one cache line between the two CPUs a two-thread run uses (docs/parallel.md,
// "The slow mode"): two threads pinned to CPUs A and B hand a counter back and forth through one
// atomic (each waits for the other's value, then writes the next), ROUNDS times; the median of
// REPEAT timings, in ns per round trip. On one chip the line moves through the shared cache (tens
// of ns); between chiplets or sockets through the interconnect (100 ns or more). A guest's vCPUs
// can be placed either way by the host, and moved.
// Usage: bench_core_latency [--cpus A B] [--rounds N] [--repeat R]
#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

namespace {

void pin_to(int cpu) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  if (pthread_setaffinity_np(pthread_self(), sizeof(set), &set) != 0) {
    std::fprintf(stderr, "bench_core_latency: cannot pin a thread to CPU %d\n", cpu);
    std::exit(1);
  }
}

struct alignas(64) Line {
  std::atomic<long> value{0};
};

// ns per round trip of `rounds` hand-overs between CPUs a and b.
double round_trip_ns(int a, int b, long rounds) {
  Line line;
  std::thread other([&] {
    pin_to(b);
    for (long k = 1; k < 2 * rounds; k += 2) {
      while (line.value.load(std::memory_order_acquire) != k) {
      }
      line.value.store(k + 1, std::memory_order_release);
    }
  });
  pin_to(a);
  const auto t0 = std::chrono::steady_clock::now();
  for (long k = 0; k < 2 * rounds; k += 2) {
    while (line.value.load(std::memory_order_acquire) != k) {
    }
    line.value.store(k + 1, std::memory_order_release);
  }
  while (line.value.load(std::memory_order_acquire) != 2 * rounds) {
  }
  const auto t1 = std::chrono::steady_clock::now();
  other.join();
  return std::chrono::duration<double, std::nano>(t1 - t0).count() / static_cast<double>(rounds);
}

}  // namespace

int main(int argc, char** argv) {
  int a = 0, b = 1, repeat = 5;
  long rounds = 200000;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--cpus") && i + 2 < argc) {
      a = std::atoi(argv[++i]);
      b = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--rounds") && i + 1 < argc) {
      rounds = std::atol(argv[++i]);
    } else if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc) {
      repeat = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: %s [--cpus A B] [--rounds N] [--repeat R]\n", argv[0]);
      return 2;
    }
  }
  std::vector<double> t;
  for (int r = 0; r < repeat; ++r) t.push_back(round_trip_ns(a, b, rounds));
  std::sort(t.begin(), t.end());
  std::printf("cpus %d %d: round trip ns min %.1f median %.1f max %.1f\n", a, b, t.front(),
              t[t.size() / 2], t.back());
  return 0;
}
