// Comparisons of whole frames shared by the tests of determinism and of resumed runs.
#pragma once

#include <gtest/gtest.h>

#include "sph/frame.hpp"

namespace sph::testing {

// The same particles in the same state, bit for bit.
inline void expectIdenticalFrames(const ParticleFrame& a, const ParticleFrame& b) {
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.position, b.position);  // exact float equality, element by element
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_EQ(a.density, b.density);
  EXPECT_EQ(a.pressure, b.pressure);
  EXPECT_EQ(a.surface, b.surface);
}

}  // namespace sph::testing
