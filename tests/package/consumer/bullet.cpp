// Uses the installed Bullet adapter (sph::bullet): a box dropped into a small tank of water.
#include <cstdio>
#include <exception>

#include <sph/bullet_engine.hpp>
#include <sph/simulation.hpp>

int main() {
  try {
    sph::Scene scene;
    scene.name = "package_consumer_bullet";
    scene.domain.box = {{-0.05, -0.05, -0.05}, {0.25, 0.3, 0.25}};
    scene.fluid.spacing = 0.01;
    sph::FluidBlock water;
    water.box = {{0.0, 0.0, 0.0}, {0.2, 0.08, 0.2}};
    scene.fluid.blocks.push_back(water);
    scene.walls.push_back(sph::WallDesc::tank({{0.0, 0.0, 0.0}, {0.2, 0.2, 0.2}}));
    scene.output.format = sph::FrameFormat::None;
    sph::Simulation sim(scene);
    sph::BulletEngine::Settings settings;
    settings.spacing = scene.fluid.spacing;
    sph::BulletEngine bullet(settings);
    const int box = bullet.addBox({0.04, 0.02, 0.04}, {0.1, 0.12, 0.1}, 500.0);
    sim.attachObjectEngine(bullet.exchange());
    for (int i = 0; i < 5; ++i) {
      sim.step();
      bullet.step();
    }
    std::printf("consumer_bullet: %llu steps, the box at y = %.4f m\n",
                static_cast<unsigned long long>(sim.stepCount()), bullet.body(box).centre[1]);
    return bullet.body(box).centre[1] < 0.12 ? 0 : 1;  // it falls
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer_bullet: %s\n", e.what());
    return 1;
  }
}
