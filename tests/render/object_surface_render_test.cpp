// Objects drawn as their surfaces: a vessel's wall drawn whole where it is whole and open where
// its springs broke, its inside showing through the hole and through the cutaway. Skipped, with
// the reason, where no offscreen context can be made.
#include <gtest/gtest.h>

#include <vector>

#include "../objects/drawn_surface_frames.hpp"
#include "../objects/object_scenes.hpp"
#include "object_surfaces.hpp"
#include "offscreen_fixture.hpp"

namespace sph::render {
namespace {

constexpr double kSpacing = 0.001;
constexpr double kRadius = 0.006;

// A vessel along x, its wall one layer of particles; `slit`: cut along x on the side facing the
// camera (+z), as a scalpel would.
objects::ObjectWorld vessel(bool slit) {
  ObjectDesc d = objects::test::tube({0, 0, 0}, kRadius, 0.03, kSpacing);
  d.deformable.model = DeformableModel::Xpbd;
  d.deformable.springReach = 2.2;
  if (slit) d.deformable.cuts = {AxisBox{{-0.005, -0.00015, 0.005}, {0.005, 0.00015, 0.007}}};
  return objects::ObjectWorld({d}, objects::test::settings());
}

class ObjectSurfaceRender : public test::OffscreenFixture {
 protected:
  ObjectSurfaceRender() : OffscreenFixture(200, 150) {}
  void SetUp() override {
    OffscreenFixture::SetUp();
    if (IsSkipped()) return;
    // Looking along -z at the vessel's side: x to the right, y up.
    camera_.target = {0.0f, 0.0f, 0.0f};
    camera_.distance = 0.045f;
    camera_.yaw = 0.0f;
    camera_.pitch = 0.0f;
    settings_.particleRadius = float(0.5 * kSpacing);
    settings_.domain = {{-0.02f, -0.01f, -0.01f}, {0.02f, 0.01f, 0.01f}};
  }

  std::vector<std::uint8_t> render(const objects::ObjectWorld& world) {
    renderer_->setObjectSurfaces({objects::test::meshOf(world.drawnSurface(0))});
    return OffscreenFixture::render(objects::test::frameOf(world.particles()));
  }

  // The brightness (sum of channels) where the world point p appears.
  int brightnessAt(const std::vector<std::uint8_t>& rgb, const Vec3f& p) const {
    const std::size_t at = pixelIndex(p);
    return rgb[at] + rgb[at + 1] + rgb[at + 2];
  }
};

const Vec3f kOnSlit{0.0f, 0.0f, float(kRadius)};        // the middle of the cut, facing us
const Vec3f kBesideSlit{0.010f, 0.0f, float(kRadius)};  // whole wall, as far from the centre

// Through the hole the far wall's inside shows, shaded darker than the wall's outside; an
// uncut vessel shows its outside at the same point.
TEST_F(ObjectSurfaceRender, ATornVesselHasAHoleWhereItsSpringsBroke) {
  const std::vector<std::uint8_t> whole = render(vessel(false));
  const std::vector<std::uint8_t> torn = render(vessel(true));
  const int outside = brightnessAt(whole, kOnSlit);
  EXPECT_GT(outside, 60) << "the uncut wall is drawn";
  EXPECT_NEAR(brightnessAt(torn, kBesideSlit), brightnessAt(whole, kBesideSlit), 6)
      << "away from the cut the wall is as it was";
  EXPECT_LT(brightnessAt(torn, kOnSlit), 0.8 * outside) << "the cut shows the inside";
  const SurfaceTriangles drawn =
      objectSurfaceTriangles({objects::test::meshOf(vessel(true).drawnSurface(0))},
                             objects::test::frameOf(vessel(true).particles()));
  EXPECT_GT(drawn.open, 0u);
}

TEST_F(ObjectSurfaceRender, TheCutawayOpensTheNearWall) {
  const objects::ObjectWorld world = vessel(false);
  const int closed = brightnessAt(render(world), kBesideSlit);
  settings_.cutaway = true;
  EXPECT_LT(brightnessAt(render(world), kBesideSlit), 0.8 * closed);
}

// As particles, the object's spheres are drawn; as a surface they are not, only the surface.
TEST_F(ObjectSurfaceRender, ParticlesAreAModeStill) {
  const objects::ObjectWorld world = vessel(true);
  const std::vector<std::uint8_t> surface = render(world);
  settings_.objectSurfaces = false;
  const std::vector<std::uint8_t> particles = render(world);
  EXPECT_NE(surface, particles);
  // The particles of the torn wall still stand by the slit, drawn as spheres.
  EXPECT_GT(brightnessAt(particles, {0.0f, 0.0015f, float(kRadius)}), 60);
}

}  // namespace
}  // namespace sph::render
