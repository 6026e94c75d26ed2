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
