// The one walk of the passes after the density pass (neighbor_walk.hpp), both widths: a pass
// that counts its pairs meets every fluid neighbour within h once, itself never, whether the
// neighbours come from the lists or, for a particle with too many to list, from the cells.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "fluid/neighbor_walk.hpp"
#include "fluid_fixture.hpp"

namespace sph::fluid {
namespace {

using namespace testing;

template <class S>
struct CountSum {
  S pairs{0.0f};
  S r2{0.0f};  // Σ r², to tell one neighbour from another
};

// Counts each particle's pairs within reach, and sums their squared distances.
struct CountingPass {
  static constexpr bool kGradients = false;
  static constexpr bool kSkipsCoincident = false;
  static constexpr bool kWalls = false;
  static constexpr bool kObjects = false;
  static constexpr std::uint32_t kColumns = 3;
  float* pairs;
  float* r2;

  template <class S, class V>
  SPH_HD_INLINE CountSum<S> start(std::size_t) const {
    return {};
  }
  template <class S, class V, class M, class C>
  SPH_HD_INLINE void addFluid(CountSum<S>& sum, const Pair<S, V, M>& pair, const C&) const {
    sum.pairs += pair.where(S(1.0f));
    sum.r2 += pair.where(pair.r2);
  }
  template <class S>
  SPH_HD_INLINE void finish(std::size_t i, const CountSum<S>& sum) const {
    pairs[i] = sumLanes(sum.pairs);
    r2[i] = sumLanes(sum.r2);
  }
};

class NeighbourWalk : public ::testing::TestWithParam<NeighborWalk> {};

struct Counts {
  std::vector<float> pairs, r2;  // by id
};

Counts countPairs(Fluid& fluid, NeighborWalk walk) {
  fluid.densityPass(walk);
  const std::size_t n = fluid.particles.count;
  std::vector<float> records(kRecordFields * (n + kBatchPadding), 1e30f);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec4 x = fluid.particles.position.data()[i];
    records[kRecordFields * i] = x.x;
    records[kRecordFields * i + 1] = x.y;
    records[kRecordFields * i + 2] = x.z;
  }
  CpuBackend::Buffer<float> pairs, r2;
  pairs.resize(n);
  r2.resize(n);
  const CountingPass pass{pairs.data(), r2.data()};
  const auto kernels = MullerKernels<float>::make(fluid.params.h);
  runPass(fluid.particles, fluid.grid, fluid.walls, fluid.objects, records.data(), kernels,
          fluid.params.periodic, walk, pass);
  return {fluid.byId(pairs), fluid.byId(r2)};
}

TEST_P(NeighbourWalk, MeetsEveryNeighbourWithinTheSupportOnce) {
  const Lattice lattice = jitteredLattice(1.0f, 0.2f, 0.0f, 21);
  Fluid fluid(lattice, KernelKind::Muller, ViscosityModel::Artificial);
  const Counts counts = countPairs(fluid, GetParam());
  for (std::size_t i = 0; i < lattice.position.size(); ++i) {
    const BruteNeighbours brute = bruteForceNeighbours(lattice.position, i, fluid.params.h);
    ASSERT_GE(counts.pairs[i], brute.surely) << "particle " << i;
    ASSERT_LE(counts.pairs[i], brute.possibly) << "particle " << i;
    if (brute.surely == brute.possibly) {
      ASSERT_NEAR(counts.r2[i], brute.r2, 1e-5 * brute.r2) << "particle " << i;
    }
  }
}

// Lists too short for any particle: every one searches the cells, and meets the same pairs.
TEST_P(NeighbourWalk, SearchesTheCellsForAParticleWithTooManyToList) {
  const Lattice lattice = jitteredLattice(1.0f, 0.2f, 0.0f, 22);
  Fluid listed(lattice, KernelKind::Muller, ViscosityModel::Artificial);
  Fluid searched(lattice, KernelKind::Muller, ViscosityModel::Artificial);
  searched.particles.neighborStride = 1;
  searched.particles.neighbors.resize(searched.particles.count);
  const Counts a = countPairs(listed, GetParam()), b = countPairs(searched, GetParam());
  for (std::uint32_t c : searched.byId(searched.particles.neighborCount))
    ASSERT_EQ(c, kNeighborOverflow);
  EXPECT_EQ(a.pairs, b.pairs);
  for (std::size_t i = 0; i < a.r2.size(); ++i) EXPECT_NEAR(a.r2[i], b.r2[i], 1e-6f * a.r2[i]);
}

SPH_BOTH_WALKS(NeighbourWalk);

}  // namespace
}  // namespace sph::fluid
