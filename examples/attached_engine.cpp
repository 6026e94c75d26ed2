// An object engine of your own beside sph's fluid: a buoy, a light box on a vertical rail, in a
// tank of water. The engine is a few lines here; yours could be any physics engine that can list
// its objects' surface particles and take forces on them.
//
// Each step the fluid reads the buoy's newest surface particles from the exchange and deposits
// its force on each; the engine takes those forces, moves the buoy and publishes it again.
// Here both run in one thread, one after the other; an engine in its own thread does the same
// at its own pace (sph/object_exchange.hpp).
//
// Usage: attached_engine [seconds]   (default 1.5: the buoy settles, and its draft is checked
// against Archimedes' within 10 %; exit status 1 if it is off)
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include <sph/object_exchange.hpp>
#include <sph/scene.hpp>
#include <sph/simulation.hpp>

namespace {

constexpr double kSpacing = 0.01;                // m, the fluid's and the buoy's particles
constexpr double kHalf[3] = {0.07, 0.04, 0.05};  // the buoy's half extents, m
constexpr double kBuoyDensity = 500.0;           // kg/m³: it floats half under
constexpr double kWaterDensity = 1000.0;

// The engine: one rigid box that moves only up and down, under gravity and the fluid's push.
class Buoy {
 public:
  explicit Buoy(double centreY) : centreY_(centreY) {
    const int n[3] = {int(std::lround(2 * kHalf[0] / kSpacing)),
                      int(std::lround(2 * kHalf[1] / kSpacing)),
                      int(std::lround(2 * kHalf[2] / kSpacing))};
    // The particles of its outer layer, one spacing apart and half a spacing inside its faces
    // (as the fluid's particles fill their own lattice cells), each with its outward normal.
    for (int i = 0; i < n[0]; ++i)
      for (int j = 0; j < n[1]; ++j)
        for (int k = 0; k < n[2]; ++k) {
          const int at[3] = {i, j, k};
          double normal[3] = {0, 0, 0};
          for (int a = 0; a < 3; ++a) {
            if (at[a] == 0) normal[a] = -1.0;
            if (at[a] == n[a] - 1) normal[a] = 1.0;
          }
          const double length =
              std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
          if (length == 0.0) continue;  // inside the box
          offsets_.push_back({-kHalf[0] + (i + 0.5) * kSpacing, -kHalf[1] + (j + 0.5) * kSpacing,
                              -kHalf[2] + (k + 0.5) * kSpacing});
          normals_.push_back({normal[0] / length, normal[1] / length, normal[2] / length});
        }
    mass_ = kBuoyDensity * 8.0 * kHalf[0] * kHalf[1] * kHalf[2];
  }

  std::size_t particleCount() const { return offsets_.size(); }
  double bottom() const { return centreY_ - kHalf[1]; }

  // Its surface particles, for the fluid's next step.
  void publish(sph::ObjectExchange& exchange, double time) const {
    sph::ObjectSurface& surface = exchange.back();
    surface.clear();
    for (std::size_t k = 0; k < offsets_.size(); ++k) {
      const auto& o = offsets_[k];
      const auto& n = normals_[k];
      surface.add(sph::Vec3{float(kCentreX + o[0]), float(centreY_ + o[1]), float(kCentreZ + o[2])},
                  sph::Vec3{0.0f, float(velocityY_), 0.0f}, float(0.5 * kSpacing),
                  sph::Vec3{float(n[0]), float(n[1]), float(n[2])}, std::uint32_t(k),
                  /*object=*/0, /*cut=*/false);
    }
    surface.time = time;
    exchange.publish();
  }

  // The mean force the fluid put on each particle since the last call, over the time it spans:
  // the buoy moves by it and by gravity over that time.
  void step(sph::ObjectExchange& exchange, double gravityY) {
    std::vector<sph::Vec3> force;
    const double span = exchange.takeForces(force);
    double lift = 0.0;
    for (const sph::Vec3& f : force) lift += f.y;
    velocityY_ += (lift / mass_ + gravityY) * span;
    centreY_ += velocityY_ * span;
  }

 private:
  static constexpr double kCentreX = 0.1, kCentreZ = 0.08;
  std::vector<std::array<double, 3>> offsets_, normals_;
  double centreY_;
  double velocityY_ = 0.0;
  double mass_ = 0.0;
};

// A tank of water 0.14 m deep.
sph::Scene tank() {
  sph::Scene s;
  s.name = "attached_engine";
  s.sourcePath = "attached_engine (example)";
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

// The water's level away from the buoy (x > 0.2): the top particle of each lattice column,
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

    // Dropped in with its bottom 2 cm above the water.
    Buoy buoy(0.14 + 0.02 + kHalf[1]);
    auto exchange = std::make_shared<sph::ObjectExchange>(buoy.particleCount());
    buoy.publish(*exchange, 0.0);
    sim.attachObjectEngine(exchange);

    const double archimedes = 2.0 * kHalf[1] * kBuoyDensity / kWaterDensity;
    double draftSum = 0.0;
    int draftSamples = 0;
    double nextReport = 0.0;
    while (sim.time() < duration) {
      sim.step(duration);
      buoy.step(*exchange, scene.gravity[1]);
      buoy.publish(*exchange, sim.time());
      if (sim.time() + 1e-9 < nextReport) continue;
      nextReport += 0.1;
      const double draft = waterLevel(sim.frame(false)) - buoy.bottom();
      std::printf("t = %.2f s: draft %.4f m (Archimedes %.4f), fluid force on it %.3f N up\n",
                  sim.time(), draft, archimedes, sim.objectStats().at(0).fluidForce[1]);
      if (sim.time() > duration - 0.3) {  // settled: average the bobbing
        draftSum += draft;
        ++draftSamples;
      }
    }
    if (duration < 1.0) return 0;  // too short to settle: nothing to check
    const double draft = draftSum / std::max(draftSamples, 1);
    const double error = (draft - archimedes) / archimedes;
    std::printf("mean draft %.4f m against Archimedes' %.4f m: %+.1f %%\n", draft, archimedes,
                100.0 * error);
    return std::abs(error) <= 0.10 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "attached_engine: %s\n", e.what());
    return 1;
  }
}
