// The step across processes against one process. Every process also runs the scene alone
// (the same decomposition over MPI_COMM_SELF: one part, no ghosts), and the particles it owns
// must match that run's bit for bit: the summation order is kept (every cell's particles in id
// order, the grid over every process's particles), so nothing but the transport differs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "distributed/communicator.hpp"
#include "distributed/fluid_decomposition.hpp"
#include "sph/error.hpp"
#include "sph/simulation.hpp"

namespace sph::distributed {
namespace {

#ifdef SPH_TESTS_SANITIZED
constexpr int kSteps = 30;  // a memory check; the comparison over 500 steps is Release's
#else
constexpr int kSteps = 500;
#endif

// A column a = 0.1 m of 16 × 16 × 8 particles collapsing in a tank 5.5 a long, 2 wall layers.
Scene damBreak() {
  const double a = 0.1;
  Scene s;
  s.name = "dam_break_distributed";
  s.sourcePath = "dam_break (distributed test)";
  s.fluid.spacing = a / 16.0;
  s.fluid.viscosity = 0.02;
  s.fluid.wallFriction = 1.0;
  s.domain.box = {{-0.05, -0.05, -0.05}, {5.5 * a + 0.05, 2.0 * a, 0.5 * a + 0.05}};
  s.fluid.blocks.push_back({{{0, 0, 0}, {a, a, 0.5 * a}}, {0, 0, 0}, false, ""});
  s.walls.push_back(WallDesc::tank({{0, 0, 0}, {5.5 * a, 1.5 * a, 0.5 * a}}, 2, false));
  return s;
}

// A column 0.1 m wide and 0.15 m high at rest in its tank.
Scene restingTank() {
  Scene s;
  s.name = "resting_tank_distributed";
  s.sourcePath = "resting_tank (distributed test)";
  s.fluid.spacing = 0.01;
  s.fluid.viscosity = 0.1;
  s.fluid.wallFriction = 1.0;
  s.domain.box = {{-0.1, -0.1, -0.1}, {0.2, 0.4, 0.2}};
  s.fluid.blocks.push_back({{{0, 0, 0}, {0.1, 0.15, 0.1}}, {0, 0, 0}, false, ""});
  s.walls.push_back(WallDesc::tank({{0, 0, 0}, {0.1, 0.2, 0.1}}, 2, false));
  return s;
}

std::shared_ptr<FluidDecomposition> across(const Communicator& comm) {
  return std::make_shared<FluidDecomposition>(comm, DecompositionSettings{});
}

// Every process's ids, on every process.
std::vector<std::uint32_t> allIds(const Communicator& world, const ParticleFrame& mine) {
  std::vector<std::byte> bytes(mine.id.size() * sizeof(std::uint32_t));
  if (!bytes.empty()) std::memcpy(bytes.data(), mine.id.data(), bytes.size());
  std::vector<std::uint32_t> out;
  for (const std::vector<std::byte>& b :
       world.exchange(std::vector<std::vector<std::byte>>(std::size_t(world.size()), bytes))) {
    const std::size_t at = out.size();
    out.resize(at + b.size() / sizeof(std::uint32_t));
    if (!b.empty()) std::memcpy(out.data() + at, b.data(), b.size());
  }
  return out;
}

// How many particles no process owns and how many two own, of ids 0 .. n-1.
struct Ownership {
  std::size_t lost = 0, duplicated = 0, foreign = 0;
};
Ownership ownership(const std::vector<std::uint32_t>& ids, std::size_t n) {
  std::vector<int> owners(n, 0);
  Ownership o;
  for (std::uint32_t id : ids) {
    if (id >= n) {
      ++o.foreign;
      continue;
    }
    ++owners[id];
  }
  for (int k : owners) {
    if (k == 0) ++o.lost;
    if (k > 1) ++o.duplicated;
  }
  return o;
}

// The particles this process owns in `many`, each against the same id in `one`, bit for bit:
// position, velocity, density and pressure. Returns how many differ.
std::size_t differing(const ParticleFrame& many, const ParticleFrame& one) {
  std::vector<std::int64_t> row(one.size(), -1);
  for (std::size_t i = 0; i < one.size(); ++i) row[one.id[i]] = std::int64_t(i);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < many.size(); ++i) {
    const std::int64_t j = many.id[i] < row.size() ? row[many.id[i]] : -1;
    if (j < 0) {
      ++differ;
      continue;
    }
    const auto same = [](const float* a, const float* b, std::size_t n) {
      return std::memcmp(a, b, n * sizeof(float)) == 0;
    };
    const std::size_t k = std::size_t(j);
    if (!same(&many.position[3 * i], &one.position[3 * k], 3) ||
        !same(&many.velocity[3 * i], &one.velocity[3 * k], 3) ||
        !same(&many.density[i], &one.density[k], 1) ||
        !same(&many.pressure[i], &one.pressure[k], 1))
      ++differ;
  }
  return differ;
}

void expectSameRunAsOneProcess(const Scene& scene, int steps = kSteps) {
  const Communicator world;
  const Communicator self(MPI_COMM_SELF);
  Simulation one(scene);
  one.distribute(across(self));
  Simulation many(scene);
  auto ranks = across(world);
  many.distribute(ranks);
  const std::size_t n = one.fluidCount();
  for (int k = 0; k < steps; ++k) {
    one.step();
    many.step();
    ASSERT_EQ(many.lastDt(), one.lastDt()) << "step " << k;
    // The incompressible solver iterates as one process does: its error is every process's.
    ASSERT_EQ(many.lastSolve().densityIterations, one.lastSolve().densityIterations) << k;
    ASSERT_EQ(many.lastSolve().divergenceIterations, one.lastSolve().divergenceIterations) << k;
    const Ownership o = ownership(allIds(world, many.frame(false)), n);
    ASSERT_EQ(o.lost, 0u) << "step " << k;
    ASSERT_EQ(o.duplicated, 0u) << "step " << k;
    ASSERT_EQ(o.foreign, 0u) << "step " << k;
  }
  const ParticleFrame mine = many.frame(false);
  EXPECT_EQ(differing(mine, one.frame(false)), 0u) << "of " << mine.size() << " owned here";
  EXPECT_EQ(many.fluidCount(), mine.size());
  EXPECT_EQ(world.sum(std::uint64_t(mine.size())), std::uint64_t(n));
  // The statistics are every process's.
  const FrameStats all = many.stats(), alone = one.stats();
  EXPECT_EQ(all.fluidCount, alone.fluidCount);
  EXPECT_EQ(all.maxSpeed, alone.maxSpeed);
  EXPECT_EQ(all.maxDensityError, alone.maxDensityError);
  EXPECT_NEAR(all.kineticEnergy, alone.kineticEnergy, 1e-9 * alone.kineticEnergy + 1e-15);
  EXPECT_NEAR(all.meanDensity, alone.meanDensity, 1e-9 * alone.meanDensity);
  // Each process owns a share and holds ghosts: the run was divided, not copied.
  if (world.size() > 1) {
    EXPECT_LT(mine.size(), n);
    const DistributedStats s = ranks->stats();
    EXPECT_GT(s.meanGhostShare, 0.0);
    // The load within a quarter of the mean (a plane of this small lattice is 6 % of it, and
    // a collapsing column moves planes fast), and over the whole run the cuts kept through
    // most steps: the first steps, a lattice settling, change each particle's work (its
    // neighbours) fast, and under the sanitizers the run is those steps only.
    EXPECT_LT(s.largestImbalance, 1.25);
    if (steps >= 500) {
      EXPECT_LT(s.repartitions, s.exchanges / 4);
    }
  }
}

TEST(DistributedStep, DamBreakMatchesOneProcessBitForBit) {
  expectSameRunAsOneProcess(damBreak());
}

TEST(DistributedStep, RestingTankMatchesOneProcessBitForBit) {
  expectSameRunAsOneProcess(restingTank());
}

// DFSPH: the solves' ghosts refreshed after each of their passes, their error reduced.
// 200 steps: each takes some 20 exchanges between the processes, which on 3 processes
// oversubscribing 2 cores wait on each other's turns.
TEST(DistributedStep, DfsphDamBreakMatchesOneProcessBitForBit) {
  Scene scene = damBreak();
  scene.fluid.solver = FluidSolver::Dfsph;
  expectSameRunAsOneProcess(scene, std::min(kSteps, 200));
}

// With continuity density the density is state and its diffusion reads the neighbours'.
TEST(DistributedStep, ContinuityDensityMatchesOneProcessBitForBit) {
  Scene scene = damBreak();
  scene.fluid.density = DensityModel::Continuity;
  expectSameRunAsOneProcess(scene);
}

// A blow-up on any process ends every process's run at the same step with the same message.
TEST(DistributedStep, AFailureEndsEveryProcessAlike) {
  const Communicator world;
  Scene scene = damBreak();
  scene.failure.maxDensityError = 0.002;  // the collapse compresses past it within steps
  const auto failure = [&](Simulation& sim) {
    try {
      for (int k = 0; k < 2000; ++k) sim.step();
    } catch (const SimulationFailure& e) {
      return std::string(e.what()) + " @" + std::to_string(sim.stepCount());
    }
    return std::string("no failure");
  };
  Simulation alone(scene);
  alone.distribute(across(Communicator(MPI_COMM_SELF)));
  const std::string expected = failure(alone);
  ASSERT_NE(expected, "no failure");
  Simulation many(scene);
  many.distribute(across(world));
  EXPECT_EQ(failure(many), expected);
}

TEST(DistributedStep, RefusesWhatIsNotYetRunAcrossProcesses) {
  const Communicator world;
  Scene scene = restingTank();
  scene.fluid.solver = FluidSolver::Pbf;
  Simulation sim(scene);
  try {
    sim.distribute(across(world));
    FAIL() << "PBF was distributed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fluid.solver is \"pbf\""), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sph::distributed
