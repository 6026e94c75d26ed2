// The CPU backend (OpenMP): the few parallel primitives a step needs. Static schedules and
// reductions combined in thread order make results depend only on the thread count.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sph::backend {

int threadCount();
void setThreadCount(int n);  // n ≤ 0: all hardware threads

// Makes the parallel primitives run on the calling thread alone. For a thread beside the one
// that steps (the frame writer): a team of its own would make OpenMP's threads outnumber the
// cores, and libgomp then lets every team's workers sleep at each barrier instead of waiting
// briefly; a 2-thread run of the artery stepped at half speed so.
void runSeriallyOnThisThread();

// For its lifetime, the calling thread's primitives use `n` threads (n ≤ 0: as they were). The
// results of a step do not depend on the count, only its speed.
class ScopedThreadCount {
 public:
  explicit ScopedThreadCount(int n);
  ~ScopedThreadCount();
  ScopedThreadCount(const ScopedThreadCount&) = delete;
  ScopedThreadCount& operator=(const ScopedThreadCount&) = delete;

 private:
  int previous_;
};

// Throws std::runtime_error when this CPU lacks the instruction set the library was compiled
// for (SPH_CPU_ARCH), instead of dying on an illegal instruction in a pass.
void requireCompiledInstructionSet();

// f(i) for every i in [0, n), in parallel.
template <class F>
void forEach(std::size_t n, F f) {
  const std::int64_t count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < count; ++i) f(static_cast<std::size_t>(i));
}

// combine over map(i), i in [0, n). Each thread reduces one contiguous chunk; chunks are
// combined in order, so floating-point sums are reproducible for a given thread count.
template <class T, class Map, class Combine>
T reduce(std::size_t n, T identity, Map map, Combine combine) {
  const int threads = threadCount();
  std::vector<T> partial(static_cast<std::size_t>(threads), identity);
#pragma omp parallel num_threads(threads)
  {
#ifdef _OPENMP
    const int t = omp_get_thread_num();
    const int used = omp_get_num_threads();
#else
    const int t = 0, used = 1;
#endif
    const std::size_t begin = n * static_cast<std::size_t>(t) / static_cast<std::size_t>(used);
    const std::size_t end = n * static_cast<std::size_t>(t + 1) / static_cast<std::size_t>(used);
    T acc = identity;
    for (std::size_t i = begin; i < end; ++i) acc = combine(acc, map(i));
    partial[static_cast<std::size_t>(t)] = acc;
  }
  T result = identity;
  for (const T& p : partial) result = combine(result, p);
  return result;
}

// In place: data[i] = sum of data[0..i). Returns the total.
std::uint32_t exclusiveScan(std::uint32_t* data, std::size_t n);

// Stable counting sort of n keys in [0, binCount). Writes `order` (sorted position → original
// index) and `binStart` (binCount + 1 entries: bin b occupies [binStart[b], binStart[b+1])).
// Stable, so the result is the same for every thread count.
void countingSort(const std::uint32_t* keys, std::size_t n, std::uint32_t binCount,
                  std::uint32_t* order, std::uint32_t* binStart);

// out[i] = in[order[i]].
template <class T>
void gather(const T* in, const std::uint32_t* order, std::size_t n, T* out) {
  forEach(n, [=](std::size_t i) { out[i] = in[order[i]]; });
}

}  // namespace sph::backend
