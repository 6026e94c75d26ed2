#include "backend/cpu_parallel.hpp"

#include <algorithm>
#include <stdexcept>

namespace sph::backend {

int threadCount() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

void requireCompiledInstructionSet() {
#if defined(__x86_64__) && defined(__AVX2__) && defined(__FMA__)
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma"))
    throw std::runtime_error(
        "this sph was compiled for AVX2 and FMA (SPH_CPU_ARCH=x86-64-v3), which this CPU "
        "lacks: rebuild with -DSPH_CPU_ARCH= (the compiler's default)");
#endif
}

void setThreadCount(int n) {
#ifdef _OPENMP
  omp_set_num_threads(n > 0 ? n : omp_get_num_procs());
#else
  (void)n;
#endif
}

void runSeriallyOnThisThread() {
#ifdef _OPENMP
  omp_set_num_threads(1);  // the calling thread's own setting
#endif
}

ScopedThreadCount::ScopedThreadCount(int n) : previous_(n > 0 ? threadCount() : 0) {
  if (n > 0) setThreadCount(n);
}

ScopedThreadCount::~ScopedThreadCount() {
  if (previous_ > 0) setThreadCount(previous_);
}

std::uint32_t exclusiveScan(std::uint32_t* data, std::size_t n) {
  std::uint32_t sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t v = data[i];
    data[i] = sum;
    sum += v;
  }
  return sum;
}

void countingSort(const std::uint32_t* keys, std::size_t n, std::uint32_t binCount,
                  std::uint32_t* order, std::uint32_t* binStart) {
  const int threads = threadCount();
  const std::size_t bins = binCount;
  // counts[t * bins + b]: keys equal to b in thread t's chunk, then that chunk's first slot.
  std::vector<std::uint32_t> counts(static_cast<std::size_t>(threads) * bins, 0u);
  auto chunkBegin = [&](int t, int used) {
    return n * static_cast<std::size_t>(t) / static_cast<std::size_t>(used);
  };
  int used = 1;
#pragma omp parallel num_threads(threads)
  {
#ifdef _OPENMP
    const int t = omp_get_thread_num();
#pragma omp single
    used = omp_get_num_threads();
#else
    const int t = 0;
#endif
    std::uint32_t* local = counts.data() + static_cast<std::size_t>(t) * bins;
    for (std::size_t i = chunkBegin(t, used); i < chunkBegin(t + 1, used); ++i) ++local[keys[i]];
#pragma omp barrier
      // Each bin's slots: all of thread 0's keys, then thread 1's, ... Bins split over threads.
#pragma omp for schedule(static)
    for (std::int64_t b = 0; b < static_cast<std::int64_t>(bins); ++b) {
      std::uint32_t total = 0;
      for (int u = 0; u < used; ++u) {
        std::uint32_t& c = counts[static_cast<std::size_t>(u) * bins + static_cast<std::size_t>(b)];
        const std::uint32_t v = c;
        c = total;
        total += v;
      }
      binStart[b] = total;
    }
#pragma omp single
    binStart[bins] = exclusiveScan(binStart, bins);
    // Implicit barrier after single: binStart holds bin offsets.
    for (std::size_t i = chunkBegin(t, used); i < chunkBegin(t + 1, used); ++i) {
      const std::uint32_t b = keys[i];
      order[binStart[b] + local[b]++] = static_cast<std::uint32_t>(i);
    }
  }
}

}  // namespace sph::backend
