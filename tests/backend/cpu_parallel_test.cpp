#include "backend/cpu_parallel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <thread>
#include <vector>

namespace sph::backend {
namespace {

std::vector<std::uint32_t> randomKeys(std::size_t n, std::uint32_t bins) {
  std::mt19937 rng(42);
  std::uniform_int_distribution<std::uint32_t> pick(0, bins - 1);
  std::vector<std::uint32_t> keys(n);
  for (auto& k : keys) k = pick(rng);
  return keys;
}

TEST(CpuParallel, CountingSortIsAStableSort) {
  const std::uint32_t bins = 97;
  const auto keys = randomKeys(10007, bins);
  std::vector<std::uint32_t> order(keys.size()), start(bins + 1);
  countingSort(keys.data(), keys.size(), bins, order.data(), start.data());

  std::vector<std::uint32_t> expected(keys.size());
  std::iota(expected.begin(), expected.end(), 0u);
  std::stable_sort(expected.begin(), expected.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
  EXPECT_EQ(order, expected);
  EXPECT_EQ(start[0], 0u);
  EXPECT_EQ(start[bins], keys.size());
  for (std::uint32_t b = 0; b < bins; ++b)
    for (std::uint32_t i = start[b]; i < start[b + 1]; ++i) EXPECT_EQ(keys[order[i]], b);
}

TEST(CpuParallel, CountingSortSameForEveryThreadCount) {
  const auto keys = randomKeys(5000, 31);
  std::vector<std::uint32_t> reference;
  for (int threads : {1, 2, 3}) {
    setThreadCount(threads);
    std::vector<std::uint32_t> order(keys.size()), start(32);
    countingSort(keys.data(), keys.size(), 31, order.data(), start.data());
    if (reference.empty()) reference = order;
    EXPECT_EQ(order, reference) << threads << " threads";
  }
  setThreadCount(0);
}

TEST(CpuParallel, EmptySortHasEmptyBins) {
  std::vector<std::uint32_t> start(5, 7u);
  countingSort(nullptr, 0, 4, nullptr, start.data());
  for (auto s : start) EXPECT_EQ(s, 0u);
}

TEST(CpuParallel, ExclusiveScan) {
  std::vector<std::uint32_t> v{3, 0, 2, 5};
  EXPECT_EQ(exclusiveScan(v.data(), v.size()), 10u);
  EXPECT_EQ(v, (std::vector<std::uint32_t>{0, 3, 3, 5}));
}

TEST(CpuParallel, ReduceSumsAndTakesMaxima) {
  const std::size_t n = 12345;
  const double sum = reduce(
      n, 0.0, [](std::size_t i) { return double(i); }, [](double a, double b) { return a + b; });
  EXPECT_DOUBLE_EQ(sum, double(n) * (n - 1) / 2);
  const int largest = reduce(
      n, -1, [](std::size_t i) { return int((i * 7919) % 1000); },
      [](int a, int b) { return std::max(a, b); });
  EXPECT_EQ(largest, 999);
}

TEST(CpuParallel, ForEachVisitsEveryIndexOnce) {
  std::vector<int> hits(1000, 0);
  int* h = hits.data();
  forEach(hits.size(), [=](std::size_t i) { h[i] += 1; });
  EXPECT_EQ(std::count(hits.begin(), hits.end(), 1), 1000);
}

TEST(CpuParallel, GatherPermutes) {
  const std::vector<float> in{10, 20, 30};
  const std::vector<std::uint32_t> order{2, 0, 1};
  std::vector<float> out(3);
  gather(in.data(), order.data(), 3, out.data());
  EXPECT_EQ(out, (std::vector<float>{30, 10, 20}));
}

// A thread beside the stepping one (the frame writer) runs the primitives on itself alone,
// with the same results, and leaves the other threads' count as it was.
TEST(CpuParallel, ASerialThreadRunsAloneAndChangesNoOtherThread) {
  setThreadCount(2);
  const int before = threadCount();
  int inside = 0;
  std::vector<int> visits(1000, 0);
  double sum = 0.0;
  std::thread beside([&] {
    runSeriallyOnThisThread();
    inside = threadCount();
    forEach(visits.size(), [&](std::size_t i) { ++visits[i]; });
    sum = reduce(
        std::size_t(100), 0.0, [](std::size_t i) { return double(i); },
        [](double a, double b) { return a + b; });
  });
  beside.join();
  EXPECT_EQ(inside, 1);
  EXPECT_EQ(threadCount(), before);
  EXPECT_EQ(std::count(visits.begin(), visits.end(), 1), 1000);
  EXPECT_EQ(sum, 4950.0);
  setThreadCount(0);
}

}  // namespace
}  // namespace sph::backend
