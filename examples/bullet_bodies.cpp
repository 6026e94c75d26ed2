// Bullet's rigid bodies in sph's water: a light box and a granite ball dropped into a tank. The
// Bullet world is the object engine (sph/bullet_engine.hpp); the fluid and it exchange surface
// particles and forces through sph::ObjectExchange, here one after the other in one thread.
//
// Usage: bullet_bodies [seconds]   (default 1.5: the box settles, and its draft is checked
// against Archimedes' within 10 % and the ball's rest on the floor; exit status 1 if not)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <utility>

#include <sph/bullet_engine.hpp>
#include <sph/scene.hpp>
#include <sph/simulation.hpp>

namespace {

constexpr double kSpacing = 0.01;  // m

sph::Scene tank() {
  sph::Scene s;
  s.name = "bullet_bodies";
  s.sourcePath = "bullet_bodies (example)";
  s.fluid.spacing = kSpacing;
  s.fluid.viscosity = 0.05;
  s.domain.box = {{-0.05, -0.05, -0.05}, {0.35, 0.45, 0.21}};
  sph::FluidBlock water;
  water.box = {{0, 0, 0}, {0.3, 0.14, 0.16}};
  water.hydrostatic = true;
  s.fluid.blocks.push_back(water);
  s.walls.push_back(sph::WallDesc::tank({{0, 0, 0}, {0.3, 0.3, 0.16}}, 2, false));
  s.calibration.maxExpectedSpeed = 1.5;
  s.output.format = sph::FrameFormat::None;
  return s;
}

// The water's level away from the bodies (x > 0.2): the top particle of each lattice column,
// averaged, plus half a spacing.
double waterLevel(const sph::ParticleFrame& f) {
  std::map<std::pair<int, int>, double> top;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double x = f.position[3 * i], y = f.position[3 * i + 1], z = f.position[3 * i + 2];
    if (x < 0.2) continue;
    const auto key = std::make_pair(int(std::floor(x / kSpacing)), int(std::floor(z / kSpacing)));
    const auto it = top.find(key);
    if (it == top.end() || y > it->second) top[key] = y;
  }
  double sum = 0.0;
  for (const auto& column : top) sum += column.second;
  return sum / double(top.size()) + 0.5 * kSpacing;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const double duration = argc > 1 ? std::atof(argv[1]) : 1.5;
    const sph::Scene scene = tank();
    sph::Simulation sim(scene);

    sph::BulletEngine::Settings settings;
    settings.spacing = kSpacing;  // the bodies' particles on the fluid's lattice
    settings.gravity = scene.gravity;
    sph::BulletEngine bullet(settings);
    const sph::BulletEngine::Vec3d half{0.06, 0.04, 0.05};
    const int box = bullet.addBox(half, {0.09, 0.2, 0.08}, 500.0);  // half the water's density
    const int ball = bullet.addSphere(0.025, {0.22, 0.2, 0.08}, 2700.0);  // granite
    bullet.addStaticBox({1.0, 0.5, 1.0}, {0.15, -0.5, 0.08});  // the tank's floor, for Bullet
    sim.attachObjectEngine(bullet.exchange());

    const double archimedes = 2.0 * half[1] * 500.0 / 1000.0;
    double draftSum = 0.0;
    int samples = 0;
    double nextReport = 0.1;
    while (sim.time() < duration) {
      sim.step(duration);
      bullet.step();  // the fluid's forces since the last step, then Bullet's substeps
      if (sim.time() + 1e-9 < nextReport) continue;
      nextReport += 0.1;
      const sph::BulletEngine::Body b = bullet.body(box), s = bullet.body(ball);
      const double draft = waterLevel(sim.frame(false)) - (b.centre[1] - half[1]);
      std::printf("t = %.2f s: box draft %.4f m (Archimedes %.4f), ball at %.4f m\n", sim.time(),
                  draft, archimedes, s.centre[1]);
      if (sim.time() > duration - 0.35) {
        draftSum += draft;
        ++samples;
      }
    }
    if (duration < 1.0) return 0;  // too short to settle: nothing to check
    const double draft = draftSum / (samples > 0 ? samples : 1);
    const double error = (draft - archimedes) / archimedes;
    const double ballHeight = bullet.body(ball).centre[1];
    std::printf("mean draft %.4f m against Archimedes' %.4f m: %+.1f %%; ball at %.4f m\n", draft,
                archimedes, 100.0 * error, ballHeight);
    return std::abs(error) <= 0.10 && std::abs(ballHeight - 0.025) < 0.0025 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bullet_bodies: %s\n", e.what());
    return 1;
  }
}
