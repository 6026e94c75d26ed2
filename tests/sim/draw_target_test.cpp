// Simulation::writeFluidForDrawing, the fluid a renderer takes without a host copy, holds the
// same particles as the frame: each id's position and quantity.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "backends.hpp"
#include "scene/scene_loader.hpp"
#include "sph/simulation.hpp"

#ifdef SPH_HAS_CUDA
#include <cuda_runtime.h>
#endif

namespace sph {
namespace {

// Arrays for `n` particles in the backend's memory, read back to the host.
class DrawArrays {
 public:
  DrawArrays(Backend backend, std::size_t n) : n_(n), device_(backend == Backend::Cuda) {
    if (!device_) {
      hostPosition_.resize(4 * n);
      hostValue_.resize(n);
      hostId_.resize(n);
      return;
    }
#ifdef SPH_HAS_CUDA
    cudaMalloc(&devicePosition_, 4 * n * sizeof(float));
    cudaMalloc(&deviceValue_, n * sizeof(float));
    cudaMalloc(&deviceId_, n * sizeof(std::uint32_t));
#endif
  }
  ~DrawArrays() {
#ifdef SPH_HAS_CUDA
    cudaFree(devicePosition_);
    cudaFree(deviceValue_);
    cudaFree(deviceId_);
#endif
  }
  FluidDrawTarget target(FluidQuantity quantity) {
    if (!device_) return {hostPosition_.data(), hostValue_.data(), hostId_.data(), n_, quantity};
    return {devicePosition_, deviceValue_, deviceId_, n_, quantity};
  }
  void readBack() {
#ifdef SPH_HAS_CUDA
    if (!device_) return;
    hostPosition_.resize(4 * n_);
    hostValue_.resize(n_);
    hostId_.resize(n_);
    cudaMemcpy(hostPosition_.data(), devicePosition_, 4 * n_ * sizeof(float),
               cudaMemcpyDeviceToHost);
    cudaMemcpy(hostValue_.data(), deviceValue_, n_ * sizeof(float), cudaMemcpyDeviceToHost);
    cudaMemcpy(hostId_.data(), deviceId_, n_ * sizeof(std::uint32_t), cudaMemcpyDeviceToHost);
#endif
  }
  const std::vector<float>& position() const {
    return hostPosition_;
  }
  const std::vector<float>& value() const {
    return hostValue_;
  }
  const std::vector<std::uint32_t>& id() const {
    return hostId_;
  }

 private:
  std::size_t n_;
  bool device_;
  std::vector<float> hostPosition_, hostValue_;
  std::vector<std::uint32_t> hostId_;
  float* devicePosition_ = nullptr;
  float* deviceValue_ = nullptr;
  std::uint32_t* deviceId_ = nullptr;
};

float speedOf(const ParticleFrame& frame, std::size_t k) {
  const float* v = &frame.velocity[3 * k];
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

class FluidDrawTargetTest : public ::testing::TestWithParam<Backend> {};

TEST_P(FluidDrawTargetTest, HoldsEachIdsPositionAndQuantity) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  const Scene scene = scene::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/artery_squeeze.json");
  Simulation sim(scene, testing::on(GetParam()));
  for (int i = 0; i < 30; ++i) sim.step();
  const ParticleFrame frame = sim.frame(false);
  std::vector<std::int64_t> slotOfId(frame.size() + 1000, -1);
  std::size_t fluid = 0;
  for (std::size_t k = 0; k < frame.size(); ++k)
    if (frame.kind[k] == std::uint8_t(ParticleKind::Fluid)) {
      ASSERT_LT(frame.id[k], slotOfId.size());
      slotOfId[frame.id[k]] = std::int64_t(k);
      ++fluid;
    }
  ASSERT_GT(fluid, 100u);

  std::size_t surface = 0;
  for (FluidQuantity quantity : {FluidQuantity::Density, FluidQuantity::Pressure,
                                 FluidQuantity::Speed, FluidQuantity::Surface}) {
    DrawArrays arrays(GetParam(), fluid + 7);
    ASSERT_EQ(sim.writeFluidForDrawing(arrays.target(quantity)), fluid);
    arrays.readBack();
    std::vector<bool> seen(slotOfId.size(), false);
    for (std::size_t i = 0; i < fluid; ++i) {
      const std::uint32_t id = arrays.id()[i];
      ASSERT_LT(id, slotOfId.size());
      ASSERT_GE(slotOfId[id], 0) << "id " << id << " is not a fluid particle of the frame";
      ASSERT_FALSE(seen[id]) << "id " << id << " written twice";
      seen[id] = true;
      const auto k = std::size_t(slotOfId[id]);
      for (int a = 0; a < 3; ++a)
        EXPECT_EQ(arrays.position()[4 * i + a], frame.position[3 * k + a]);
      EXPECT_EQ(arrays.position()[4 * i + 3], 1.0f);
      const float value = arrays.value()[i];
      switch (quantity) {
        case FluidQuantity::Density:
          EXPECT_EQ(value, frame.density[k]);
          break;
        case FluidQuantity::Pressure:
          EXPECT_EQ(value, frame.pressure[k]);
          break;
        case FluidQuantity::Speed:
          EXPECT_NEAR(value, speedOf(frame, k), 1e-6f * (1.0f + speedOf(frame, k)));
          break;
        case FluidQuantity::Surface:
          EXPECT_EQ(value, frame.surface[k] ? 1.0f : 0.0f);
          surface += frame.surface[k];
          break;
        case FluidQuantity::None:
          break;
      }
    }
  }
  EXPECT_GT(surface, 0u);  // the surface case compared both values
}

TEST_P(FluidDrawTargetTest, TooSmallOrMisalignedIsRefusedAndWritesNothing) {
  SPH_SKIP_UNLESS_AVAILABLE(GetParam());
  const Scene scene = scene::loadScene(std::string(SPH_SOURCE_DIR) + "/scenes/artery_squeeze.json");
  Simulation sim(scene, testing::on(GetParam()));
  const std::size_t n = sim.fluidCount();
  std::vector<float> position(4 * n + 4, -7.0f), value(n, -7.0f);
  FluidDrawTarget small{position.data(), value.data(), nullptr, n - 1, FluidQuantity::Density};
  EXPECT_THROW(sim.writeFluidForDrawing(small), std::invalid_argument);
  FluidDrawTarget noValue{position.data(), nullptr, nullptr, n, FluidQuantity::Density};
  EXPECT_THROW(sim.writeFluidForDrawing(noValue), std::invalid_argument);
  FluidDrawTarget misaligned{position.data() + 1, value.data(), nullptr, n, FluidQuantity::Density};
  EXPECT_THROW(sim.writeFluidForDrawing(misaligned), std::invalid_argument);
  for (float x : position) ASSERT_EQ(x, -7.0f);
  for (float x : value) ASSERT_EQ(x, -7.0f);
}

SPH_ON_EVERY_BACKEND(FluidDrawTargetTest);

}  // namespace
}  // namespace sph
