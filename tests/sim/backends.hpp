// The backends the physics tests run on. The CPU always; CUDA where this build has it, and
// skipped, with the reason, where there is no GPU.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "sph/devices.hpp"
#include "sph/simulation.hpp"

namespace sph::testing {

// Built with the sanitizers (tests/CMakeLists.txt): long runs check that they run clean and
// leave their physics figures to the Release build.
#ifdef SPH_TESTS_SANITIZED
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

// Runs too long for the test command (a minute or more) are skipped unless SPH_LONG_TESTS is
// set: scripts/validate-artery sets it for the ones it names.
inline bool longRuns() {
  const char* set = std::getenv("SPH_LONG_TESTS");
  return set != nullptr && *set != '\0' && *set != '0';
}

inline std::string backendTestName(const ::testing::TestParamInfo<Backend>& info) {
  return info.param == Backend::Cuda ? "cuda" : "cpu";
}

// Call first in a test on `backend`: skips it when that backend cannot run here.
#define SPH_SKIP_UNLESS_AVAILABLE(backend)                                 \
  do {                                                                     \
    if ((backend) == ::sph::Backend::Cuda) {                               \
      const ::sph::GpuReport gpus = ::sph::queryGpus();                    \
      if (gpus.devices.empty()) GTEST_SKIP() << "no GPU: " << gpus.reason; \
    }                                                                      \
  } while (false)

inline SimulationOptions on(Backend backend) {
  SimulationOptions options;
  options.backend = backend;
  return options;
}

#define SPH_ON_EVERY_BACKEND(suite)                                                      \
  INSTANTIATE_TEST_SUITE_P(Backends, suite,                                              \
                           ::testing::Values(::sph::Backend::Cpu, ::sph::Backend::Cuda), \
                           ::sph::testing::backendTestName)

}  // namespace sph::testing
