#include "sim/calibration.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>

#include "sim/sampling.hpp"
#include "sph/core/contact.hpp"
#include "sph/core/eos.hpp"
#include "sph/core/kernels.hpp"
#include "sph/core/time_step.hpp"
#include "sph/error.hpp"

namespace sph::sim {

namespace {

// The 2021 CUDA SPH tutorial: threshold 7.065 with a support radius of 2/64.
constexpr double kTutorialSurfaceThresholdTimesH = 7.065 * 2.0 / 64.0;

template <class Kernels>
double latticeSum(const Kernels& kernels, double h, double spacing) {
  const int reach = static_cast<int>(std::ceil(h / spacing));
  double sum = 0.0;
  for (int k = -reach; k <= reach; ++k)
    for (int j = -reach; j <= reach; ++j)
      for (int i = -reach; i <= reach; ++i)
        sum += kernels.W(spacing * spacing * double(i * i + j * j + k * k));
  return sum;
}

// Σ_j |∇W(x_i - x_j)|² over an infinite cubic lattice.
template <class Kernels>
double gradientSquaresOnLattice(const Kernels& kernels, double h, double spacing) {
  const int reach = static_cast<int>(std::ceil(h / spacing));
  double sum = 0.0;
  for (int k = -reach; k <= reach; ++k)
    for (int j = -reach; j <= reach; ++j)
      for (int i = -reach; i <= reach; ++i) {
        const double r = spacing * std::sqrt(double(i * i + j * j + k * k));
        const double g = kernels.gradFactor(r) * r;
        sum += g * g;
      }
  return sum;
}

double gravityMagnitude(const Scene& scene) {
  const auto& g = scene.gravity;
  return std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
}

// The lowest point of a wall's shape along the up axis (`sign` +1 when up is +axis); a mesh's
// is not known before it is read, and does not count.
double lowestHeight(const WallDesc& wall, int up, double sign) {
  const auto height = [&](double coordinate) { return sign * coordinate; };
  switch (wall.kind) {
    case WallKind::Tank:
    case WallKind::Box:
      return std::min(height(wall.box.min[up]), height(wall.box.max[up]));
    case WallKind::Sphere:
      return height(wall.center[up]) - wall.radius;
    case WallKind::Cylinder: {
      const double length = std::sqrt(wall.axis[0] * wall.axis[0] + wall.axis[1] * wall.axis[1] +
                                      wall.axis[2] * wall.axis[2]);
      const double along = length > 0.0 ? std::abs(wall.axis[up]) / length : 0.0;
      return height(wall.center[up]) - 0.5 * wall.length * along -
             wall.radius * std::sqrt(std::max(0.0, 1.0 - along * along));
    }
    case WallKind::Plane: {
      double lowest = HUGE_VAL;
      for (double a : {0.0, 1.0})
        for (double b : {0.0, 1.0})
          lowest =
              std::min(lowest, height(wall.corner[up] + a * wall.edge1[up] + b * wall.edge2[up]));
      return lowest;
    }
    case WallKind::Mesh:
      break;
  }
  return HUGE_VAL;
}

// Height of the highest fluid above the lowest floor, along gravity.
double fallHeight(const Scene& scene) {
  const int up = upAxisOf(scene.gravity);
  const double sign = scene.gravity[up] <= 0.0 ? 1.0 : -1.0;  // +1 when "up" is +axis
  auto height = [&](double coordinate) { return sign * coordinate; };
  double top = -HUGE_VAL, floor = HUGE_VAL;
  for (const auto& block : scene.fluid.blocks) {
    top = std::max({top, height(block.box.min[up]), height(block.box.max[up])});
    floor = std::min({floor, height(block.box.min[up]), height(block.box.max[up])});
  }
  for (const EmitterDesc& e : scene.emitters) {  // what enters there falls from there
    const Vec3d& at = e.shape == EmitterShape::Disc ? e.center : e.corner;
    top = std::max(top, height(at[up]));
    floor = std::min(floor, height(at[up]));
  }
  for (const WallDesc& wall : scene.walls) floor = std::min(floor, lowestHeight(wall, up, sign));
  if (scene.domain.dampedBox)
    floor = std::min({floor, height(scene.domain.box.min[up]), height(scene.domain.box.max[up])});
  return top > floor ? top - floor : 0.0;
}

// The fastest a block starts (its velocity, and its spin at the corners) or an emitter puts
// fluid in.
double largestBlockSpeed(const Scene& scene) {
  const auto norm = [](const Vec3d& u) {
    return std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  };
  double v = 0.0;
  for (const auto& block : scene.fluid.blocks) {
    const Vec3d halfDiagonal{0.5 * (block.box.max[0] - block.box.min[0]),
                             0.5 * (block.box.max[1] - block.box.min[1]),
                             0.5 * (block.box.max[2] - block.box.min[2])};
    v = std::max(v, norm(block.velocity) + norm(block.angularVelocity) * norm(halfDiagonal));
  }
  for (const EmitterDesc& e : scene.emitters) v = std::max(v, e.speed);
  return v;
}

// Meteer 2011, §8.1 for the interaction: the paper tuned its contact coefficients by hand; ours
// follow from the fluid. The spring is as stiff as the fluid's CFL step can resolve at the centre
// of the influence sphere, where the distance function is largest (e^β):
// ω = sqrt(k e^β / m) = 1 / dt_CFL. The dashpot is half critical for that spring at its rim. A
// fluid particle's acceleration is clamped at c0² / h, the pressure acceleration of a fully
// compressed neighbourhood, far above what a calm flow sees.
void calibrateContact(const Scene& scene, Calibration& out) {
  const InteractionDesc& i = scene.interaction;
  out.objectsAsBoundary = i.coupling == ObjectCoupling::Boundary;
  const double cflDt = scene.time.cfl * out.supportRadius / out.soundSpeed;
  const double peak = distanceFunctionPeak(i.distanceExponent);
  out.contactStiffnessFromScene = i.stiffness.has_value();
  out.contactStiffness = i.stiffness ? *i.stiffness : out.mass / (cflDt * cflDt * peak);
  out.contactDampingFromScene = i.damping.has_value();
  out.contactDamping = i.damping ? *i.damping : std::sqrt(out.contactStiffness * out.mass);
  out.contactShearFromScene = i.shear.has_value();
  out.contactShear = i.shear ? *i.shear : 0.0;
  out.maxAccelerationFromScene = i.maxAcceleration.has_value();
  out.maxAcceleration =
      i.maxAcceleration ? *i.maxAcceleration : out.soundSpeed * out.soundSpeed / out.supportRadius;
}

}  // namespace

interaction::InteractionParameters interactionParameters(const Scene& scene, const Calibration& c) {
  const InteractionDesc& i = scene.interaction;
  interaction::InteractionParameters p;
  p.contact =
      ContactCoefficients{static_cast<float>(c.contactStiffness),
                          static_cast<float>(c.contactDamping), static_cast<float>(c.contactShear)};
  p.distance = DistanceFunctionTable::make(i.distanceExponent);
  p.fluidRadius = static_cast<float>(0.5 * c.spacing);
  p.influenceRatio = static_cast<float>(i.influenceRatio);
  p.fluidMass = static_cast<float>(c.mass);
  p.maxAcceleration = static_cast<float>(c.maxAcceleration);
  p.cutAwareDamping = i.cutAwareDamping;
  p.boundary = c.objectsAsBoundary;
  return p;
}

// Object against object: as stiff as the fluid contact at its peak, with the same damping
// ratio; the object engine substeps as this needs.
objects::WorldSettings worldSettings(const Scene& scene, const Calibration& c) {
  objects::WorldSettings w;
  w.gravity = Vec3{static_cast<float>(scene.gravity[0]), static_cast<float>(scene.gravity[1]),
                   static_cast<float>(scene.gravity[2])};
  w.defaultSpacing = static_cast<float>(c.spacing);
  const double spring =
      c.contactStiffness * distanceFunctionPeak(scene.interaction.distanceExponent);
  w.contact = ContactCoefficients{static_cast<float>(spring),
                                  static_cast<float>(std::sqrt(spring * c.mass)), 0.0f};
  const AxisBox& domain = scene.domain.box;
  w.regionMin = Vec3{float(domain.min[0]), float(domain.min[1]), float(domain.min[2])};
  w.regionMax = Vec3{float(domain.max[0]), float(domain.max[1]), float(domain.max[2])};
  float* regionMin[3] = {&w.regionMin.x, &w.regionMin.y, &w.regionMin.z};
  float* regionMax[3] = {&w.regionMax.x, &w.regionMax.y, &w.regionMax.z};
  double* lo[3] = {&w.periodic.lo.x, &w.periodic.lo.y, &w.periodic.lo.z};
  double* length[3] = {&w.periodic.length.x, &w.periodic.length.y, &w.periodic.length.z};
  for (int a = 0; a < 3; ++a) {
    if (!scene.domain.periodic[a]) continue;
    w.periodic.periodic[a] = true;
    *lo[a] = domain.min[a];
    *length[a] = domain.max[a] - domain.min[a];
    // An object is whole on one side or the other of a face: parts of it lie outside.
    *regionMin[a] = -3.0e38f;
    *regionMax[a] = 3.0e38f;
  }
  // Under boundary coupling the fluid is incompressible and its solve holds the objects still:
  // a vessel it fills must keep its volume by itself (objects/volume_constraint.hpp). Under
  // contact coupling the weakly compressible fluid's pressure tells the vessel.
  if (scene.interaction.coupling == ObjectCoupling::Boundary)
    for (const FluidBlock& block : scene.fluid.blocks)
      for (std::size_t o = 0; o < scene.objects.size(); ++o)
        if (!block.inside.empty() && scene.objects[o].name == block.inside &&
            std::find(w.liquidFilled.begin(), w.liquidFilled.end(), o) == w.liquidFilled.end())
          w.liquidFilled.push_back(o);
  w.sourceName = scene.sourcePath;
  w.sceneFolder = std::filesystem::path(scene.sourcePath).parent_path().string();
  return w;
}

double latticeKernelSum(KernelKind kernel, double h, double spacing) {
  switch (kernel) {
    case KernelKind::CubicSpline:
      return latticeSum(CubicSplineKernels<double>::make(h), h, spacing);
    case KernelKind::WendlandC2:
      return latticeSum(WendlandC2Kernels<double>::make(h), h, spacing);
    default:
      return latticeSum(MullerKernels<double>::make(h), h, spacing);
  }
}

double latticeGradientSquares(KernelKind kernel, double h, double spacing) {
  switch (kernel) {
    case KernelKind::CubicSpline:
      return gradientSquaresOnLattice(CubicSplineKernels<double>::make(h), h, spacing);
    case KernelKind::WendlandC2:
      return gradientSquaresOnLattice(WendlandC2Kernels<double>::make(h), h, spacing);
    default:
      return gradientSquaresOnLattice(MullerKernels<double>::make(h), h, spacing);
  }
}

namespace {

// The position solver's substeps and its relaxation ε (core/pbf.hpp).
void calibratePositions(const Scene& scene, Calibration& out) {
  const TimeDesc& t = scene.time;
  out.substepsFromScene = t.substeps > 0;
  const double travel = kPbfSubstepTravel * out.spacing;
  out.substeps =
      t.substeps > 0
          ? t.substeps
          : std::max(1, int(std::ceil(t.frameDt * out.maxExpectedSpeed / travel * (1.0 - 1e-12))));
  // On a full lattice G = 0: the constraint gradient's sum is Σ_j |V ∇W_ij|².
  const double volume = out.mass / scene.fluid.restDensity;
  out.pbfGradientSquares =
      volume * volume * latticeGradientSquares(scene.fluid.kernel, out.supportRadius, out.spacing);
  const double substep = t.fixedDt ? *t.fixedDt : t.frameDt / out.substeps;
  out.pbfSpeedGuard = kPbfGuardMove * out.supportRadius / substep;
}

}  // namespace

Calibration calibrate(const Scene& scene, bool attachedEngine) {
  const FluidDesc& f = scene.fluid;
  const CalibrationDesc& c = scene.calibration;
  Calibration out;
  out.spacing = f.spacing;
  out.supportRadius = f.supportRatio * f.spacing;

  out.massFromScene = c.mass.has_value();
  out.mass =
      c.mass ? *c.mass : f.restDensity / latticeKernelSum(f.kernel, out.supportRadius, f.spacing);

  out.maxExpectedSpeedFromScene = c.maxExpectedSpeed.has_value();
  const double v0 = largestBlockSpeed(scene);
  const double fall = freeFallSpeed(gravityMagnitude(scene), fallHeight(scene));
  out.maxExpectedSpeed =
      c.maxExpectedSpeed ? *c.maxExpectedSpeed : std::sqrt(v0 * v0 + fall * fall);

  out.soundSpeedFromScene = c.speedOfSound.has_value();
  if (c.speedOfSound) {
    out.soundSpeed = *c.speedOfSound;
  } else if (out.maxExpectedSpeed > 0.0) {
    out.soundSpeed = soundSpeedForMaxSpeed(out.maxExpectedSpeed);
  } else {
    throw InputError(scene.sourcePath +
                     ": calibration.speed_of_sound: cannot be derived (no gravity and no initial "
                     "velocity, so no speed is expected); set calibration.speed_of_sound or "
                     "calibration.max_expected_speed");
  }

  out.stiffnessFromScene = c.stiffness.has_value();
  out.stiffness =
      c.stiffness ? *c.stiffness : stiffnessForSoundSpeed(f.eos, out.soundSpeed, f.restDensity);

  // Artificial viscosity acts like ν = α h c0 / 10 in 3-D (Monaghan 2005).
  out.kinematicViscosity = f.viscosityModel == ViscosityModel::Muller
                               ? f.viscosity / f.restDensity
                               : f.viscosity * out.supportRadius * out.soundSpeed / 10.0;

  out.surfaceThreshold = f.surfaceThreshold ? *f.surfaceThreshold
                                            : kTutorialSurfaceThresholdTimesH / out.supportRadius;

  if (!scene.objects.empty() || attachedEngine) calibrateContact(scene, out);

  if (f.solver == FluidSolver::Pbf) calibratePositions(scene, out);

  // The fluid starts at rest, under gravity alone.
  out.initialDt =
      scene.time.fixedDt ? *scene.time.fixedDt
      : f.solver == FluidSolver::Pbf
          ? scene.time.frameDt / out.substeps
          : longestStep(stepLimits(scene, out), 0.0,
                        std::hypot(scene.gravity[0], scene.gravity[1], scene.gravity[2]));
  return out;
}

StepLimits stepLimits(const Scene& scene, const Calibration& c) {
  const TimeDesc& t = scene.time;
  StepLimits l;
  l.followsFlow = scene.fluid.solver == FluidSolver::Dfsph;
  l.cfl = t.cfl;
  l.h = c.supportRadius;
  l.soundSpeed = c.soundSpeed;
  l.forceFactor = l.followsFlow ? scene.fluid.dfsph.forceFactor : t.forceFactor;
  l.viscousFactor = t.viscousFactor;
  l.kinematicViscosity = c.kinematicViscosity;
  l.wallFriction = scene.fluid.wallFriction;
  l.maxDt = t.maxDt;
  return l;
}

fluid::FluidParameters fluidParameters(const Scene& scene, const Calibration& c) {
  const FluidDesc& f = scene.fluid;
  fluid::FluidParameters p;
  p.kernel = f.kernel;
  p.eos = f.eos;
  p.pressureForm = f.pressureForm;
  p.viscosityModel = f.viscosityModel;
  p.clampNegativePressure = f.clampNegativePressure;
  p.pressureForces = f.solver == FluidSolver::Wcsph;
  p.h = static_cast<float>(c.supportRadius);
  p.mass = static_cast<float>(c.mass);
  p.restDensity = static_cast<float>(f.restDensity);
  p.stiffness = static_cast<float>(c.stiffness);
  p.soundSpeed = static_cast<float>(c.soundSpeed);
  p.viscosity = static_cast<float>(f.viscosity);
  p.wallFriction = static_cast<float>(f.wallFriction);
  p.surfaceTension = static_cast<float>(f.surfaceTension);
  p.surfaceThreshold = static_cast<float>(c.surfaceThreshold);
  p.continuityDensity = f.density == DensityModel::Continuity;
  p.densityDiffusion = static_cast<float>(f.densityDiffusion);
  p.gravity = Vec3{static_cast<float>(scene.gravity[0]), static_cast<float>(scene.gravity[1]),
                   static_cast<float>(scene.gravity[2])};
  p.periodic = periodicity(scene, p.h);
  return p;
}

Periodicity periodicity(const Scene& scene, float support) {
  const DomainDesc& d = scene.domain;
  std::uint32_t axes = 0;
  for (int a = 0; a < 3; ++a)
    if (d.periodic[a]) axes |= 1u << a;
  auto v = [](const Vec3d& x) {
    return Vec3{static_cast<float>(x[0]), static_cast<float>(x[1]), static_cast<float>(x[2])};
  };
  return makePeriodicity(axes, v(d.box.min), v(d.box.max), support);
}

fluid::DomainParameters domainParameters(const Scene& scene) {
  const DomainDesc& d = scene.domain;
  auto v = [](const Vec3d& a) {
    return Vec3{static_cast<float>(a[0]), static_cast<float>(a[1]), static_cast<float>(a[2])};
  };
  fluid::DomainParameters out{v(d.box.min),
                              v(d.box.max),
                              d.outside == OutsidePolicy::Clamp,
                              d.dampedBox,
                              static_cast<float>(d.damping),
                              {},
                              {}};
  static_assert(kMaxOutlets <= fluid::kOutletSlots, "an outlet the stage has no slot for");
  for (const OutletDesc& o : scene.outlets) {
    out.outlets.min[out.outlets.count] = v(o.box.min);
    out.outlets.max[out.outlets.count] = v(o.box.max);
    ++out.outlets.count;
  }
  return out;
}

EngineSetup engineSetup(const Scene& scene, const Calibration& calibration, const Walls& walls) {
  EngineSetup setup;
  setup.params = fluidParameters(scene, calibration);
  setup.domain = domainParameters(scene);
  setup.domain.periodic = setup.params.periodic;
  setup.walls = walls.particles();
  // About twice the neighbours of a particle in the initial lattice leaves room for
  // compression. A multiple of 16 indices (a cache line): 64 for h = 2d, which measured 6 %
  // faster at 262,144 particles than 68, the lists spreading over less memory.
  const double ratio = scene.fluid.supportRatio;
  const double twiceLattice = 2.0 * 4.0 / 3.0 * kPi * ratio * ratio * ratio;
  setup.neighborStride =
      16u * static_cast<std::uint32_t>(std::max(1.0, std::round(twiceLattice / 16.0)));
  return setup;
}

}  // namespace sph::sim
