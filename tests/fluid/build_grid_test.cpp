// Building the grid (build_grid.hpp): the particles sorted by cell, each array reordered with
// them and every id kept once; a particle outside the domain or in an outlet removed and
// counted.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "fluid_fixture.hpp"

namespace sph::fluid {
namespace {

using namespace testing;

TEST(BuildGridStage, SortsByCellAndKeepsEachParticlesState) {
  const Lattice lattice = jitteredLattice(1.0f, 0.4f, 1.0f, 3);
  Fluid fluid(lattice, KernelKind::Muller, ViscosityModel::Artificial);
  EXPECT_EQ(buildGrid(fluid.particles, fluid.grid, fluid.domain), 0u);
  const std::size_t n = lattice.position.size();
  ASSERT_EQ(fluid.particles.count, n);
  std::vector<std::uint32_t> cells(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 x = xyz(fluid.particles.position.data()[i]);
    cells[i] = cellIndex(fluid.grid.spec,
                         clampToGrid(fluid.grid.spec, cellCoordinate(fluid.grid.spec, x)));
    // The particle's cell range holds it.
    const std::uint32_t* start = fluid.grid.cellStart.data();
    EXPECT_GE(i, start[cells[i]]);
    EXPECT_LT(i, start[cells[i] + 1]);
  }
  EXPECT_TRUE(std::is_sorted(cells.begin(), cells.end()));
  const std::vector<Vec4> x = fluid.byId(fluid.particles.position);
  const std::vector<Vec4> v = fluid.byId(fluid.particles.velocity);
  for (std::size_t id = 0; id < n; ++id) {
    EXPECT_EQ(xyz(x[id]).x, lattice.position[id].x);
    EXPECT_EQ(xyz(x[id]).z, lattice.position[id].z);
    EXPECT_EQ(xyz(v[id]).y, lattice.velocity[id].y);
  }
  std::vector<std::uint32_t> ids(fluid.particles.id.data(), fluid.particles.id.data() + n);
  std::sort(ids.begin(), ids.end());
  for (std::size_t k = 0; k < n; ++k) ASSERT_EQ(ids[k], k);
}

// Shared by a distributed run's processes: the grid spans the bounds given, and each cell's
// particles are in id order (ghost bit aside) whatever order they came in.
TEST(BuildGridStage, ASharedGridSpansTheBoundsGivenAndOrdersEachCellById) {
  const Lattice lattice = jitteredLattice(1.0f, 0.4f, 1.0f, 5);
  Fluid fluid(lattice, KernelKind::Muller, ViscosityModel::Artificial);
  const std::size_t n = lattice.position.size();
  // Reversed ids, every third a ghost: a sort keeping the input order would list each cell's
  // particles by falling id.
  for (std::size_t i = 0; i < n; ++i)
    fluid.particles.id.data()[i] = std::uint32_t(n - 1 - i) | (i % 3 == 0 ? kGhostBit : 0u);
  fluid.grid.shared = true;
  fluid.grid.sharedLo = Vec3{-0.5f, -0.5f, -0.5f};
  fluid.grid.sharedHi = Vec3{1.5f, 1.5f, 1.5f};
  EXPECT_EQ(buildGrid(fluid.particles, fluid.grid, fluid.domain), 0u);
  EXPECT_EQ(fluid.grid.spec.origin.x, -0.5f);
  const std::uint32_t* id = fluid.particles.id.data();  // reordered by the sort
  const std::uint32_t* start = fluid.grid.cellStart.data();
  std::size_t ordered = 0;
  for (std::uint32_t c = 0; c < fluid.grid.spec.cellCount; ++c)
    for (std::uint32_t k = start[c] + 1; k < start[c + 1]; ++k) {
      ASSERT_LT(id[k - 1] & ~kGhostBit, id[k] & ~kGhostBit) << "cell " << c;
      ++ordered;
    }
  EXPECT_GT(ordered, n / 2);  // cells of several particles were ordered
}

TEST(BuildGridStage, RemovesWhatLeftTheDomainOrEnteredAnOutlet) {
  const Lattice lattice = jitteredLattice(1.0f, 0.0f, 0.0f, 4);
  Fluid fluid(lattice, KernelKind::Muller, ViscosityModel::Artificial);
  fluid.domain.max = Vec3{0.0451f, 1.0f, 1.0f};  // x up to 4.5 spacings: the first 5 layers stay
  fluid.domain.outlets.count = 1;
  fluid.domain.outlets.min[0] = Vec3{-1.0f, -1.0f, -1.0f};
  fluid.domain.outlets.max[0] = Vec3{1.0f, 0.0051f, 1.0f};  // the bottom layer, y = 0
  EXPECT_EQ(buildGrid(fluid.particles, fluid.grid, fluid.domain), 1000u - 5u * 9u * 10u);
  EXPECT_EQ(fluid.particles.count, 5u * 9u * 10u);
  for (std::size_t i = 0; i < fluid.particles.count; ++i) {
    const Vec3 x = xyz(fluid.particles.position.data()[i]);
    EXPECT_LE(x.x, 0.0451f);
    EXPECT_GT(x.y, 0.0051f);
  }
}

}  // namespace
}  // namespace sph::fluid
