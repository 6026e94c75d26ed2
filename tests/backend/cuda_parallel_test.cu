// The CUDA backend's primitives give the CPU backend's results. Without a GPU each test
// reports itself skipped, with the reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "backend/cpu_parallel.hpp"
#include "backend/cuda/cuda_parallel.cuh"
#include "backend/cuda/cuda_reduce.cuh"
#include "sph/devices.hpp"

namespace sph::backend::cuda {
namespace {

class CudaParallel : public ::testing::Test {
 protected:
  void SetUp() override {
    const GpuReport gpus = queryGpus();
    if (gpus.devices.empty()) GTEST_SKIP() << "no GPU: " << gpus.reason;
  }
};

std::vector<std::uint32_t> randomKeys(std::size_t n, std::uint32_t bins) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::uint32_t> pick(0, bins - 1);
  std::vector<std::uint32_t> keys(n);
  for (auto& k : keys) k = pick(rng);
  return keys;
}

TEST_F(CudaParallel, CountingSortMatchesTheCpuBackend) {
  const std::uint32_t bins = 1000;
  const auto keys = randomKeys(100003, bins);
  std::vector<std::uint32_t> cpuOrder(keys.size()), cpuStart(bins + 1);
  backend::countingSort(keys.data(), keys.size(), bins, cpuOrder.data(), cpuStart.data());

  DeviceBuffer<std::uint32_t> dKeys, dOrder(keys.size()), dStart(bins + 1);
  dKeys.copyFromHost(keys.data(), keys.size());
  SortScratch scratch;
  countingSort(dKeys.data(), keys.size(), bins, dOrder.data(), dStart.data(), scratch);
  std::vector<std::uint32_t> order(keys.size()), start(bins + 1);
  dOrder.copyToHost(order.data(), order.size());
  dStart.copyToHost(start.data(), start.size());
  EXPECT_EQ(start, cpuStart);
  EXPECT_EQ(order, cpuOrder) << "both sorts are stable";
}

// nvcc wants device lambdas in functions with public access: outside the TEST bodies.
void fillModulo977(float* v, std::size_t n) {
  forEach(n, [=] __device__(std::size_t i) { v[i] = static_cast<float>(i % 977); });
}

float largestOf(const float* v, std::size_t n) {
  return reduce(
      n, 0.0f, [=] __host__ __device__(std::size_t i) { return v[i]; },
      [] __host__ __device__(float a, float b) { return a > b ? a : b; });
}

TEST_F(CudaParallel, ForEachGatherAndReduce) {
  const std::size_t n = 50000;
  DeviceBuffer<float> values(n), gathered(n);
  float* v = values.data();
  fillModulo977(v, n);
  std::vector<std::uint32_t> order(n);
  std::iota(order.rbegin(), order.rend(), 0u);  // reversed
  DeviceBuffer<std::uint32_t> dOrder;
  dOrder.copyFromHost(order.data(), n);
  gather(values.data(), dOrder.data(), n, gathered.data());
  std::vector<float> host(n);
  gathered.copyToHost(host.data(), n);
  EXPECT_EQ(host.front(), static_cast<float>((n - 1) % 977));
  EXPECT_EQ(host.back(), 0.0f);

  EXPECT_EQ(largestOf(v, n), 976.0f);
}

TEST_F(CudaParallel, ExclusiveScan) {
  std::vector<std::uint32_t> data{3, 0, 2, 5};
  DeviceBuffer<std::uint32_t> d;
  d.copyFromHost(data.data(), data.size());
  EXPECT_EQ(exclusiveScan(d.data(), data.size()), 10u);
  d.copyToHost(data.data(), data.size());
  EXPECT_EQ(data, (std::vector<std::uint32_t>{0, 3, 3, 5}));
}

// Runs everywhere: the message of a failed call names the call and the place.
TEST(CudaCheck, ErrorNamesCallFileAndLine) {
  try {
    check(cudaErrorInvalidValue, "cudaMemcpy(dst, src, n, kind)", "fluid/forces.cu", 42);
    FAIL() << "an error status must throw";
  } catch (const CudaError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("cudaMemcpy(dst, src, n, kind)"), std::string::npos) << message;
    EXPECT_NE(message.find("fluid/forces.cu:42"), std::string::npos) << message;
    EXPECT_NE(message.find("cudaErrorInvalidValue"), std::string::npos) << message;
  }
  EXPECT_NO_THROW(check(cudaSuccess, "cudaFree(p)", "x.cu", 1));
}

TEST(CudaDevices, ReportSaysWhyThereIsNoGpu) {
  const GpuReport report = queryGpus();
  EXPECT_TRUE(report.cudaBuilt);
  if (report.devices.empty()) EXPECT_FALSE(report.reason.empty());
}

}  // namespace
}  // namespace sph::backend::cuda
