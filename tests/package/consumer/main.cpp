// Uses the installed library as an outside project would: a scene built in code, a few steps.
#include <cstdio>
#include <exception>

#include <sph/scene.hpp>
#include <sph/scene_file.hpp>
#include <sph/simulation.hpp>

int main() {
  try {
    sph::Scene scene;
    scene.name = "package_consumer";
    scene.domain.box = {{0.0, 0.0, 0.0}, {0.2, 0.2, 0.2}};
    scene.domain.dampedBox = true;
    scene.fluid.spacing = 0.01;
    // 8 × 8 × 8 = 512 particles on the lattice.
    sph::FluidBlock block;
    block.box = {{0.0, 0.0, 0.0}, {0.08, 0.08, 0.08}};
    scene.fluid.blocks.push_back(block);
    scene.output.format = sph::FrameFormat::None;

    // The same scene through the public scene reader, written and read back.
    const sph::Scene reread = sph::parseScene(sph::sceneToJsonText(scene), "consumer.json");
    if (reread.fluid.blocks.size() != 1 || reread.fluid.spacing != 0.01) {
      std::fprintf(stderr, "consumer: the scene did not survive sceneToJsonText/parseScene\n");
      return 1;
    }

    sph::Simulation sim(reread);
    for (int i = 0; i < 5; ++i) sim.step();

    std::printf("consumer: %llu steps, %llu fluid particles, t = %g s\n",
                static_cast<unsigned long long>(sim.stepCount()),
                static_cast<unsigned long long>(sim.fluidCount()), sim.time());
    if (sim.stepCount() != 5 || sim.fluidCount() == 0) {
      std::fprintf(stderr, "consumer: expected 5 steps and some fluid\n");
      return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
}
