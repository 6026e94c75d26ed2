// Periodic boundaries (core/periodic.hpp): separations to the nearest image, positions back
// inside the period, and which particles need either.
#include "sph/core/periodic.hpp"

#include <gtest/gtest.h>

namespace sph {
namespace {

const Periodicity kBox = makePeriodicity(1u | 4u, Vec3{0, -1, 0}, Vec3{1, 1, 2}, 0.1f);

TEST(Periodic, SeparationsGoToTheNearestImageAlongPeriodicAxesOnly) {
  const Vec3 d = minimumImage(kBox, Vec3{0.9f, 1.9f, -1.9f});
  EXPECT_NEAR(d.x, -0.1f, 1e-6f);  // across the x faces: 0.1 the other way
  EXPECT_NEAR(d.y, 1.9f, 1e-6f);   // y is not periodic
  EXPECT_NEAR(d.z, 0.1f, 1e-6f);
  const Vec3 inside = minimumImage(kBox, Vec3{0.3f, 0.2f, -0.7f});
  EXPECT_FLOAT_EQ(inside.x, 0.3f);  // already the nearest
  EXPECT_FLOAT_EQ(inside.z, -0.7f);
}

TEST(Periodic, OnlyParticlesWithinReachOfAPeriodicFaceAreNearASeam) {
  EXPECT_TRUE(nearSeam(kBox, Vec3{0.05f, 0.0f, 1.0f}));
  EXPECT_TRUE(nearSeam(kBox, Vec3{0.5f, 0.0f, 1.95f}));
  EXPECT_FALSE(nearSeam(kBox, Vec3{0.5f, 0.0f, 1.0f}));
  EXPECT_FALSE(nearSeam(kBox, Vec3{0.5f, -0.99f, 1.0f}));  // by a face that is not periodic
  EXPECT_FALSE(nearSeam(Periodicity{}, Vec3{0.0f, 0.0f, 0.0f}));
}

TEST(Periodic, APositionThatLeftThroughAFaceComesBackThroughTheOther) {
  const Vec3 x = wrapIntoDomain(kBox, Vec3{1.02f, 1.5f, -0.25f});
  EXPECT_NEAR(x.x, 0.02f, 1e-6f);
  EXPECT_FLOAT_EQ(x.y, 1.5f);  // not periodic: left to the domain's other rules
  EXPECT_NEAR(x.z, 1.75f, 1e-6f);
  // A hair outside a face, where adding the period rounds onto the far face itself.
  const Vec3 edge = wrapIntoDomain(kBox, Vec3{-1e-9f, 0.0f, 0.5f});
  EXPECT_GE(edge.x, 0.0f);
  EXPECT_LT(edge.x, 1.0f);
}

TEST(Periodic, TheBatchFormMatchesTheOneAtATimeForm) {
  const Vec3 a{0.95f, 0.3f, 1.97f}, b{0.02f, -0.4f, 0.01f};
  const Vec3 one = minimumImage(kBox, a - b);
  const BatchVec3 batch = minimumImage(kBox, broadcast(a) - broadcast(b));
  for (std::size_t k = 0; k < FloatBatch::size(); ++k) {
    EXPECT_FLOAT_EQ(batch.x[k], one.x);
    EXPECT_FLOAT_EQ(batch.y[k], one.y);
    EXPECT_FLOAT_EQ(batch.z[k], one.z);
  }
}

}  // namespace
}  // namespace sph
