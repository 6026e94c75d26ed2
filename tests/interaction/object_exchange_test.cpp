#include "sph/object_exchange.hpp"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

namespace sph {
namespace {

TEST(ObjectExchange, TheFluidReadsEachPublicationOnce) {
  ObjectExchange exchange(4);
  std::uint64_t seen = 0;
  EXPECT_FALSE(exchange.readIfNew(seen, [](const ObjectSurface&) {}));
  exchange.back().add(Vec3{1, 2, 3}, Vec3{0, 0, 1}, 0.5f, Vec3{0, 1, 0}, 3, 0, false);
  exchange.publish();
  std::size_t read = 0;
  EXPECT_TRUE(exchange.readIfNew(seen, [&](const ObjectSurface& s) {
    read = s.size();
    EXPECT_EQ(s.handle[0], 3u);
    EXPECT_EQ(s.position[0].w, 0.5f);
  }));
  EXPECT_EQ(read, 1u);
  EXPECT_FALSE(exchange.readIfNew(seen, [](const ObjectSurface&) {}));
}

TEST(ObjectExchange, ForcesAreTheMeanOverTheDepositedSteps) {
  ObjectExchange exchange(3);
  const std::uint32_t handles[] = {2, 0};
  const Vec4 first[] = {{1, 0, 0, 0}, {0, 4, 0, 0}};
  const Vec4 second[] = {{3, 0, 0, 0}, {0, 0, 0, 0}};
  exchange.depositForces(handles, first, 2, 0.001);
  exchange.depositForces(handles, second, 2, 0.003);
  std::vector<Vec3> forces;
  EXPECT_DOUBLE_EQ(exchange.takeForces(forces), 0.004);
  ASSERT_EQ(forces.size(), 3u);
  // (1·0.001 + 3·0.003) / 0.004 = 2.5; (4·0.001) / 0.004 = 1.
  EXPECT_NEAR(forces[2].x, 2.5f, 1e-6f);
  EXPECT_NEAR(forces[0].y, 1.0f, 1e-6f);
  EXPECT_EQ(forces[1].x, 0.0f);
  // An engine faster than the fluid keeps the last mean until the next deposit.
  std::vector<Vec3> again;
  EXPECT_EQ(exchange.takeForces(again), 0.0);
  EXPECT_EQ(again[2].x, forces[2].x);
}

TEST(ObjectExchange, AHandleOutsideTheCountIsRefused) {
  ObjectExchange exchange(2);
  exchange.back().add(Vec3{0, 0, 0}, Vec3{0, 0, 0}, 0.5f, Vec3{0, 1, 0}, 2, 0, false);
  EXPECT_THROW(exchange.publish(), std::out_of_range);
}

TEST(ObjectExchange, AnEngineThreadAndTheFluidShareItSafely) {
  ObjectExchange exchange(64);
  std::thread engine([&] {
    for (int step = 0; step < 2000; ++step) {
      std::vector<Vec3> forces;
      exchange.takeForces(forces);
      ObjectSurface& s = exchange.back();
      s.clear();
      for (std::uint32_t k = 0; k < 64; ++k)
        s.add(Vec3{float(step), 0, 0}, Vec3{0, 0, 0}, 0.5f, Vec3{1, 0, 0}, k, 0, false);
      exchange.publish();
    }
  });
  std::uint64_t seen = 0;
  std::vector<std::uint32_t> handles(64);
  std::vector<Vec4> forces(64, Vec4{1, 0, 0, 0});
  for (std::uint32_t k = 0; k < 64; ++k) handles[k] = k;
  for (int step = 0; step < 2000; ++step) {
    exchange.readIfNew(seen, [&](const ObjectSurface& s) {
      // A publication is never seen half written: all its particles agree.
      ASSERT_EQ(s.size(), 64u);
      for (std::size_t k = 1; k < s.size(); ++k) ASSERT_EQ(s.position[k].x, s.position[0].x);
    });
    exchange.depositForces(handles.data(), forces.data(), 64, 1e-4);
  }
  engine.join();
}

}  // namespace
}  // namespace sph
