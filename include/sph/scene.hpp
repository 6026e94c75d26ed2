// The description of a simulation as read from a scene file: geometry, material, parameters,
// output. Plain data; `scene/scene_loader` fills it from JSON, `sim/calibration` derives the rest.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "sph/core/options.hpp"

namespace sph {

using Vec3d = std::array<double, 3>;

enum class OutsidePolicy { Remove, Clamp };
enum class FrameFormat { Vtp, Ply, Csv, None };

struct AxisBox {
  Vec3d min{0, 0, 0};
  Vec3d max{0, 0, 0};
};

// A block of fluid sampled on a cubic lattice of the fluid spacing. A hydrostatic block starts
// compressed as it would rest under gravity, so a tank starts at rest instead of dropping into
// its own compression and ringing.
// `inside` names an object: only the lattice points in that object's interior are kept, so a
// vessel can be filled completely.
struct FluidBlock {
  AxisBox box;
  Vec3d velocity{0, 0, 0};
  bool hydrostatic = false;
  std::string inside;
  Vec3d angularVelocity{0, 0, 0};  // rad/s, a rigid spin about the box's centre
};

// Static walls, sampled as boundary particles with their volumes (Akinci et al. 2012), on the
// side away from the fluid, `layers` deep, half a spacing behind the surface the fluid meets.
enum class WallKind {
  Tank,      // the inner faces are `box`; no lid unless `closed`
  Box,       // `box`: a solid obstacle, or a closed tank when the fluid is inside
  Sphere,    // `center`, `radius`
  Cylinder,  // `center`, `axis`, `radius`, `length` (end to end); discs at the ends if `capped`
  Plane,     // the parallelogram `corner` + a `edge1` + b `edge2`, a, b in [0, 1]: the face of
             // a solid behind it; the fluid on the side edge1 × edge2 points to
  Mesh       // OBJ or STL, scaled by `scale`, its origin at `center`; the fluid on the side the
             // triangles' normals point to (right-handed winding)
};

// Which side of a box, sphere or cylinder the fluid is on.
enum class FluidSide { Outside, Inside };

struct WallDesc {
  std::string name;  // for force probes; the loader gives "wall<i>" when unset
  WallKind kind = WallKind::Tank;
  int layers = 2;
  AxisBox box;                           // tank, box
  bool closed = false;                   // tank
  FluidSide fluid = FluidSide::Outside;  // box, sphere, cylinder
  Vec3d center{0, 0, 0};                 // sphere, cylinder, mesh
  double radius = 0.0;                   // sphere, cylinder
  double length = 0.0;                   // cylinder
  Vec3d axis{0, 1, 0};                   // cylinder; any length but zero
  bool capped = true;                    // cylinder
  Vec3d corner{0, 0, 0};                 // plane
  Vec3d edge1{0, 0, 0};                  // plane
  Vec3d edge2{0, 0, 0};                  // plane
  std::string meshFile;                  // mesh, resolved against the scene's folder
  double scale = 1.0;                    // mesh
  bool open = false;                     // mesh: holes are meant (a sheet, a pipe's ends)

  static WallDesc tank(const AxisBox& inner, int layers = 2, bool closed = false) {
    WallDesc w;
    w.box = inner;
    w.layers = layers;
    w.closed = closed;
    return w;
  }
};

struct DomainDesc {
  AxisBox box;
  OutsidePolicy outside = OutsidePolicy::Remove;
  // Reflect at the domain faces, velocity scaled by -damping (the 2021 CUDA SPH tutorial).
  bool dampedBox = false;
  double damping = 0.5;
  // Axes (x, y, z) along which the domain's two faces are one: what leaves through one enters
  // through the other, and the fluid near one face feels the fluid and walls near the other.
  std::array<bool, 3> periodic{false, false, false};
};

// The incompressible solver (fluid.solver "dfsph"; Bender & Koschier 2015): when its two
// solves stop.
struct DfsphDesc {
  double densityTolerance = 0.0005;    // average ρ/ρ0 - 1 predicted at the end of the step
  double divergenceTolerance = 0.001;  // average Δt (Dρ/Dt) / ρ0
  int minIterations = 1;
  int maxIterations = 100;
  bool warmStart = true;  // each solve starts from the last step's pressure
  // Either solve can be left out to see what the other does: the divergence solve alone keeps
  // a velocity field from compressing but lets density errors drift; the density solve alone
  // is the constant-density solver of the papers.
  bool divergenceSolve = true;
  bool densitySolve = true;
  // The step under acceleration: Δt ≤ force_factor √(h / a_max). The solve predicts the
  // density linearly over the step; past about 0.1 the prediction fails near walls.
  double forceFactor = 0.1;
  // The share of a coarse-grid solve's pressure added to the density solve's first iteration
  // (docs/solvers.md): the smooth part of the error at once, where Jacobi takes a pass a
  // neighbourhood. 0 leaves it out.
  double coarseCorrection = 0.7;
};

// The position solver (fluid.solver "pbf"; Macklin & Müller 2013): its iterations a substep and
// its constants. The substeps are time.frame_dt's.
struct PbfDesc {
  int iterations = 3;
  // ε, the density constraint's relaxation, as a share D of the constraint gradient's sum on a
  // full lattice. Jacobi moves a particle and its neighbours at once, so the full correction
  // (0) overshoots; at 1 a uniformly compressed region is corrected about once, not twice: a
  // resting tank's kinetic energy fell 40-fold from 0.01's, its pressure noise from 10 % to 1 %.
  double relaxation = 1.0;
  // k of the tensile correction s_corr = -k (W(r)/W(Δq))⁴ / D, D the constraint gradient's sum
  // on a full lattice: k is the compression whose multiplier the correction matches at Δq.
  // Macklin & Müller's k has no D, and so depends on the scene's scale.
  double tensileStrength = 0.01;
  double tensileDistance = 0.2;  // Δq / h
  double xsph = 0.01;            // c, XSPH's smoothing of the velocities
};

struct FluidDesc {
  double restDensity = 1000.0;  // kg/m³
  double spacing = 0.01;        // lattice spacing d, m
  double supportRatio = 2.0;    // h / d
  FluidSolver solver = FluidSolver::Wcsph;
  DfsphDesc dfsph;
  PbfDesc pbf;
  KernelKind kernel = KernelKind::Muller;
  EquationOfState eos = EquationOfState::Linear;
  bool clampNegativePressure = true;
  DensityModel density = DensityModel::Summation;
  double densityDiffusion = 0.1;  // δ of δ-SPH, with continuity density
  PressureForm pressureForm = PressureForm::Symmetric;
  ViscosityModel viscosityModel = ViscosityModel::Artificial;
  // α (dimensionless) for artificial; μ (Pa·s) for Müller, whose scenes give it (the loader's
  // default for it is water's, 0.001).
  double viscosity = 0.1;
  // The fraction of the fluid's viscosity that acts against walls: 0 free slip, 2 no-slip.
  // Neither default is 0: the walls' mirrored pressure is not the gradient of an energy and
  // pumps energy into the fluid, which only viscosity against the walls takes out. A block of
  // water at rest in a tank went through the walls inviscid, and also with α = 0.1 and no
  // friction (docs/validation.md, "Walls and viscosity").
  double wallFriction = 1.0;
  double surfaceTension = 0.0;  // σ (N/m); 0 disables
  // |∇c| (1/m) above which a particle is on the surface and surface tension acts; unset: 0.22/h,
  // the 2021 CUDA SPH tutorial's 7.065 at its h = 1/32, scaled to ours.
  std::optional<double> surfaceThreshold;
  std::vector<FluidBlock> blocks;
};

// Values `sim/calibration` derives unless the scene sets them.
struct CalibrationDesc {
  std::optional<double> mass;              // kg per particle
  std::optional<double> maxExpectedSpeed;  // m/s; default sqrt(2 g H)
  std::optional<double> speedOfSound;      // m/s; default 10 × max expected speed
  std::optional<double> stiffness;         // k or B, by equation of state
};

struct TimeDesc {
  double duration = 1.0;         // simulated seconds
  double cfl = 0.4;              // dt ≤ cfl h / (c0 + vmax)
  double forceFactor = 0.25;     // dt ≤ forceFactor sqrt(h / amax)
  double viscousFactor = 0.125;  // dt ≤ viscousFactor h² / ν
  double maxDt = 1e-2;
  std::optional<double> fixedDt;
  // The position solver's frame step, cut into substeps: by default as many as keep every
  // particle from moving more than 0.4 of its radius in one at the largest expected speed.
  double frameDt = 1.0 / 60.0;
  int substeps = 0;  // 0: derived
};

struct OutputDesc {
  double fps = 30.0;
  FrameFormat format = FrameFormat::Vtp;
  double probeRate = 1000.0;  // probe samples per simulated second, independent of frames
};

// A probe (scene "probes"): what it reads is sampled at output.probe_rate into probes.csv.
enum class ProbeKind {
  Point,  // pressure, density and velocity at `position` (core/probe.hpp)
  Level,  // the free surface along the line `from` → `to`: its distance from `from`
  Force   // the fluid's force on `object` or on `wall`
};

struct ProbeDesc {
  std::string name;
  ProbeKind kind = ProbeKind::Point;
  Vec3d position{0, 0, 0};  // Point
  Vec3d from{0, 0, 0};      // Level
  Vec3d to{0, 0, 0};        // Level
  std::string object;       // Force: an object's name, or
  std::string wall;         // Force: a wall's name
};

// Flow in (scene "emitters"): fluid enters through a disc or a rectangle on the fluid's
// lattice, a layer each time the last has moved one spacing on, at `speed` along the shape's
// normal, from `start` to `end`. The fluid within two spacings downstream is held at that
// velocity, so that what is downstream cannot push it back through the opening.
enum class EmitterShape {
  Disc,      // `center`, `radius`, flowing along `direction`
  Rectangle  // the parallelogram `corner` + a `edge1` + b `edge2`, flowing along edge1 × edge2
};

struct EmitterDesc {
  std::string name;  // the loader gives "emitter<i>" when unset
  EmitterShape shape = EmitterShape::Disc;
  Vec3d center{0, 0, 0};     // disc
  double radius = 0.0;       // disc
  Vec3d direction{1, 0, 0};  // disc; any length but zero
  Vec3d corner{0, 0, 0};     // rectangle
  Vec3d edge1{0, 0, 0};      // rectangle
  Vec3d edge2{0, 0, 0};      // rectangle
  double speed = 0.0;        // m/s
  double start = 0.0;        // s
  double end = 1e30;         // s; emits while start <= t < end
};

// The most emitters and outlets a scene may have: the stages that drive and drain them take
// their geometry as one small value.
inline constexpr std::size_t kMaxEmitters = 8;
inline constexpr std::size_t kMaxOutlets = 8;

// Flow out (scene "outlets"): fluid that enters `box` is removed and counted.
struct OutletDesc {
  std::string name;  // the loader gives "outlet<i>" when unset
  AxisBox box;
};

struct FailureDesc {
  double maxDensityError = 0.5;  // compression ρ/ρ0 - 1 past which the run stops as failed
  // m/s: a particle faster stops the run as failed; unset: ten times the speed of sound (ten
  // times the largest expected speed under DFSPH), which only a blow-up reaches.
  std::optional<double> maxSpeed;
};

// What a scene may make, checked before anything is: beyond them it is refused (0: no bound
// but the machine's memory).
struct LimitsDesc {
  double maxParticles = 0.0;  // fluid, wall and object particles together
  double maxMemoryGb = 0.0;   // the particles' memory, GB (1e9 bytes)
};

// Particle-based objects (Meteer 2011, §4.3, §7) for the built-in object engine (src/objects).
enum class ObjectMotion { Rigid, Deformable, Kinematic };
enum class ShapeKind { Box, Sphere, Capsule, Tube, Mesh };

// The shape an object's particles are sampled from, at its initial pose.
struct ShapeDesc {
  ShapeKind kind = ShapeKind::Box;
  Vec3d center{0, 0, 0};       // of the box, sphere, capsule, tube; the mesh's origin goes here
  Vec3d halfExtents{0, 0, 0};  // box
  double radius = 0.0;         // sphere, capsule; tube: radius of the wall's particle layer
  double length = 0.0;         // capsule, tube: distance between the end centres along `axis`
  Vec3d axis{1, 0, 0};         // capsule, tube; any length but zero
  bool capped = true;          // tube: closed by flat discs at both ends
  std::string meshFile;        // mesh: OBJ or STL, resolved against the scene's folder
  double scale = 1.0;          // mesh: multiplies the file's coordinates
  bool solid = false;          // sample the whole volume, not only the surface
  int layers = 1;              // surface sampling: layers of particles, inwards
};

// A kinematic object follows these keyframes: at `time` it is moved by `offset` and turned by
// `rotation` (axis × angle in radians) from its initial pose, about its initial centre.
// Linear in between; held after the last.
struct KeyframeDesc {
  double time = 0.0;
  Vec3d offset{0, 0, 0};
  Vec3d rotation{0, 0, 0};
};

// How a deformable's springs are integrated: as explicit forces (Hooke plus a dashpot, substeps
// as short as the stiffest spring needs), or as XPBD distance constraints of compliance 1/k
// (Macklin et al. 2016, 2019), a fixed number of substeps whatever the stiffness.
enum class DeformableModel { Springs, Xpbd };

// A deformable object: its particles are joined by springs to every particle within
// `springReach` × spacing at rest.
struct DeformableDesc {
  double stiffness = 0.0;       // N/m per spring; 0: derived (object engine)
  double damping = 0.0;         // N·s/m along each spring; 0: derived (critical over a spring)
  double breakingStrain = 0.0;  // a spring breaks past |l - l0| / l0; 0: never
  double springReach = 1.5;     // × the object's spacing, in (1, kMaxSpringReach]
  // The loader's and the object engine's one limit: past three spacings a solid's springs per
  // particle grow as the reach's cube, to about a hundred.
  static constexpr double kMaxSpringReach = 3.0;
  std::vector<AxisBox> pinned;  // particles inside these boxes are fixed
  std::vector<AxisBox> cuts;    // springs that pass through these start broken (a slit)
  DeformableModel model = DeformableModel::Springs;
  int substeps = 8;  // xpbd: substeps per engine step, each one constraint iteration
  // xpbd: N/m of a bending constraint on each nearly straight line of three nearest neighbours
  // (the middle's distance from the three's centroid, Kelager et al. 2010); 0: none.
  double bendingStiffness = 0.0;
};

struct ObjectDesc {
  std::string name;
  ObjectMotion motion = ObjectMotion::Rigid;
  ShapeDesc shape;
  double density = 1000.0;  // kg/m³ of the material; a surface layer is `spacing` thick
  double spacing = 0.0;     // particle spacing, m; 0: the fluid's
  Vec3d velocity{0, 0, 0};
  Vec3d angularVelocity{0, 0, 0};  // rad/s, rigid bodies
  DeformableDesc deformable;
  std::vector<KeyframeDesc> keyframes;
};

// How the fluid and the objects push each other. Contact: Meteer 2011's contact forces through
// influence spheres (eqs. 13-16), a spring and dampers whose stiffness bounds the time step.
// Boundary: the objects' surface particles count in the fluid's density and in the
// incompressible solver's pressure as boundary particles (Akinci et al. 2012), and take the
// reactions of that pressure; needs fluid.solver "dfsph" (docs/solvers.md says what it does
// well and what not yet).
enum class ObjectCoupling { Contact, Boundary };

// Fluid–object contact (Meteer 2011, §7.4, §8.2, §8.3). Unset values are derived by calibration.
struct InteractionDesc {
  ObjectCoupling coupling = ObjectCoupling::Contact;
  double influenceRatio = 1.5;            // influence sphere radius / object particle radius
  double distanceExponent = 4.0;          // β of the distance function exp(β (1 - q))
  std::optional<double> stiffness;        // k_spring, N/m
  std::optional<double> damping;          // k_damping, N·s/m
  std::optional<double> shear;            // k_shear, N·s/m
  std::optional<double> maxAcceleration;  // clamp on a fluid particle's acceleration, m/s²
  bool cutAwareDamping = true;            // no damping against particles whose springs broke
};

// Which engine moves the scene's objects. Builtin: src/objects, made by the Simulation.
// Bullet: a Bullet world (sph/bullet_engine.hpp, BulletEngine::forScene) that whoever runs the
// scene attaches (`sph run` does); the Simulation makes none of the objects itself.
enum class ObjectEngineKind { Builtin, Bullet };

// How the object engine runs beside the fluid (Meteer 2011, figure 1).
struct ObjectEngineDesc {
  ObjectEngineKind type = ObjectEngineKind::Builtin;
  double rate = 1.0;      // engine steps per fluid step: 2 runs it twice as often, 0.5 half
  bool ownThread = true;  // in its own thread, in lock-step with the fluid (deterministic)
};

// How `sph render` and `sph view` draw the scene's fluid (scene "render"): as a liquid surface
// or as particles; a liquid's colour where it is deep and how fast it absorbs the light through
// it (Beer–Lambert: a layer t thick lets exp(−a t) through, per colour channel). The defaults
// are clear water's; blood is about colour [0.3, 0.015, 0.02], absorption [300, 3000, 3000].
enum class FluidLook { Liquid, Particles };

struct RenderDesc {
  FluidLook look = FluidLook::Liquid;
  Vec3d colour{0.18, 0.50, 0.80};     // RGB, each in [0, 1]
  Vec3d absorption{40.0, 12.0, 6.0};  // 1/m per channel
};

struct Scene {
  std::string name;
  std::string description;
  std::string sourcePath;  // file it was read from, for messages
  DomainDesc domain;
  Vec3d gravity{0, -9.81, 0};
  FluidDesc fluid;
  std::vector<WallDesc> walls;
  std::vector<ObjectDesc> objects;
  InteractionDesc interaction;
  ObjectEngineDesc objectEngine;
  CalibrationDesc calibration;
  TimeDesc time;
  OutputDesc output;
  std::vector<ProbeDesc> probes;
  std::vector<EmitterDesc> emitters;
  std::vector<OutletDesc> outlets;
  FailureDesc failure;
  LimitsDesc limits;
  RenderDesc render;
};

}  // namespace sph
