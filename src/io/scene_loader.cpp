#include "io/scene_loader.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <system_error>
#include <utility>

#include <nlohmann/json.hpp>

#include "io/json_input.hpp"
#include "io/scene_checks.hpp"
#include "io/scene_flow.hpp"
#include "io/scene_overrides.hpp"
#include "io/scene_reader.hpp"
#include "io/scene_schema.hpp"
#include "sph/error.hpp"

namespace sph::io {
namespace {

using nlohmann::json;

constexpr NumberRule kSupportRatio{1, 4, false, false};
constexpr NumberRule kDiffusion{0, 1, false, false};  // δ; 0.1 is the usual

DomainDesc readDomain(const ObjectReader& in) {
  DomainDesc domain;
  domain.box = readBox(in);
  domain.outside = in.choice("outside", domain.outside, kOutsideNames);
  domain.dampedBox = in.boolean("damped_box", domain.dampedBox);
  domain.damping = in.number("damping", domain.damping, kClosedUnit);
  const std::string axes = in.string("periodic", "");
  for (char axis : axes) {
    const std::size_t a = std::string("xyz").find(axis);
    if (a == std::string::npos || domain.periodic[a])
      in.context().fail(in.keyPath("periodic"),
                        "expected the periodic axes as letters x, y and z, each at most once "
                        "(\"xz\"; \"\" for none), got \"" +
                            axes + "\"");
    domain.periodic[a] = true;
  }
  return domain;
}

void readViscosity(const ObjectReader& in, FluidDesc& fluid) {
  fluid.viscosityModel = in.choice("model", fluid.viscosityModel, kViscosityNames);
  constexpr double kWaterViscosity = 0.001;  // Pa·s, at 20 °C
  fluid.viscosity = in.number(
      "value", fluid.viscosityModel == ViscosityModel::Muller ? kWaterViscosity : fluid.viscosity,
      kNonNegative);
  fluid.wallFriction = in.number("wall_friction", fluid.wallFriction, kNonNegative);
}

DfsphDesc readDfsph(const ObjectReader& in) {
  DfsphDesc d;
  d.densityTolerance = in.number("density_tolerance", d.densityTolerance, kOpenUnit);
  d.divergenceTolerance = in.number("divergence_tolerance", d.divergenceTolerance, kOpenUnit);
  d.minIterations = in.integer("min_iterations", d.minIterations, 0, 1000);
  // No fewer than the minimum: the range the message states says so.
  d.maxIterations = in.integer("max_iterations", std::max(d.maxIterations, d.minIterations),
                               std::max(d.minIterations, 1), 10000);
  d.warmStart = in.boolean("warm_start", d.warmStart);
  d.divergenceSolve = in.boolean("divergence_solve", d.divergenceSolve);
  d.densitySolve = in.boolean("density_solve", d.densitySolve);
  d.forceFactor = in.number("force_factor", d.forceFactor, kUnitStep);
  return d;
}

FluidDesc readFluid(const ObjectReader& in) {
  FluidDesc fluid;
  fluid.restDensity = in.number("rest_density", fluid.restDensity, kDensity);
  fluid.spacing = in.number("spacing", fluid.spacing, kSpacing);
  fluid.supportRatio = in.number("support_ratio", fluid.supportRatio, kSupportRatio);
  fluid.solver = in.choice("solver", fluid.solver, kSolverNames);
  fluid.dfsph = readDfsph(in.object("dfsph"));
  fluid.kernel = in.choice("kernel", fluid.kernel, kKernelNames);
  fluid.eos = in.choice("eos", fluid.eos, kEosNames);
  fluid.clampNegativePressure = in.boolean("clamp_negative_pressure", fluid.clampNegativePressure);
  fluid.pressureForm = in.choice("pressure_form", fluid.pressureForm, kPressureFormNames);
  fluid.density = in.choice("density", fluid.density, kDensityModelNames);
  fluid.densityDiffusion = in.number("density_diffusion", fluid.densityDiffusion, kDiffusion);
  readViscosity(in.object("viscosity"), fluid);
  const ObjectReader tension = in.object("surface_tension");
  fluid.surfaceTension = tension.number("coefficient", fluid.surfaceTension, kSurfaceTension);
  fluid.surfaceThreshold = tension.optionalNumber("threshold", kPositive);
  for (const ObjectReader& blockIn : in.objectArray("blocks", /*required=*/true,
                                                    /*nonEmpty=*/true)) {
    FluidBlock block;
    block.box = readBox(blockIn);
    block.velocity = blockIn.vec3("velocity", block.velocity, kLargestVelocity);
    block.hydrostatic = blockIn.boolean("hydrostatic", block.hydrostatic);
    block.inside = blockIn.string("inside", block.inside);
    block.angularVelocity = blockIn.vec3("angular_velocity", block.angularVelocity, kLargestSpin);
    fluid.blocks.push_back(block);
  }
  return fluid;
}

// A key that belongs to another type of wall is a mistake, not something to ignore.
void refuseOtherTypesKeys(const ObjectReader& in, WallKind kind) {
  const std::vector<std::string>& keys = wallKeys(kind);
  for (const KeySchema& key : sceneSchema().child("walls").element().children) {
    if (key.name == "name" || key.name == "type" || key.name == "layers" || !in.has(key.name))
      continue;
    if (std::find(keys.begin(), keys.end(), key.name) != keys.end()) continue;
    std::string list;
    for (const std::string& k : keys) list += (list.empty() ? "" : ", ") + k;
    in.context().fail(in.keyPath(key.name), std::string("not a key of a ") +
                                                nameOf(kind, kWallKindNames) +
                                                " wall; its keys are name, type, layers, " + list);
  }
}

double requiredLength(const ObjectReader& in, const std::string& key) {
  const std::optional<double> value = in.optionalNumber(key, kPositive);
  if (!value) in.context().fail(in.keyPath(key), "required key is missing (a length in m)");
  return *value;
}

WallDesc readWall(const ObjectReader& in, std::size_t index) {
  WallDesc w;
  w.name = in.string("name", "wall" + std::to_string(index));
  w.kind = in.choice("type", w.kind, kWallKindNames);
  w.layers = in.integer("layers", w.layers, 1, 4);
  refuseOtherTypesKeys(in, w.kind);
  switch (w.kind) {
    case WallKind::Tank:
      w.box = readBox(in);
      w.closed = in.boolean("closed", w.closed);
      break;
    case WallKind::Box:
      w.box = readBox(in);
      w.fluid = in.choice("fluid", w.fluid, kFluidSideNames);
      break;
    case WallKind::Sphere:
      w.center = in.requiredVec3("center");
      w.radius = requiredLength(in, "radius");
      w.fluid = in.choice("fluid", w.fluid, kFluidSideNames);
      break;
    case WallKind::Cylinder:
      w.center = in.requiredVec3("center");
      w.radius = requiredLength(in, "radius");
      w.length = requiredLength(in, "length");
      w.axis = in.vec3("axis", w.axis);
      w.capped = in.boolean("capped", w.capped);
      w.fluid = in.choice("fluid", w.fluid, kFluidSideNames);
      break;
    case WallKind::Plane:
      w.corner = in.requiredVec3("corner");
      w.edge1 = in.requiredVec3("edge1");
      w.edge2 = in.requiredVec3("edge2");
      break;
    case WallKind::Mesh:
      w.meshFile = in.string("file", w.meshFile);
      if (w.meshFile.empty())
        in.context().fail(in.keyPath("file"), "expected the path of an OBJ or STL file");
      w.center = in.vec3("center", w.center);
      w.scale = in.number("scale", w.scale, kScale);
      w.open = in.boolean("open", w.open);
      break;
  }
  return w;
}

std::vector<WallDesc> readWalls(const ObjectReader& root) {
  std::vector<WallDesc> walls;
  for (const ObjectReader& in : root.objectArray("walls", /*required=*/false,
                                                 /*nonEmpty=*/false))
    walls.push_back(readWall(in, walls.size()));
  return walls;
}

std::vector<AxisBox> readBoxes(const ObjectReader& in, const std::string& key) {
  std::vector<AxisBox> boxes;
  for (const ObjectReader& boxIn : in.objectArray(key, /*required=*/false, /*nonEmpty=*/false))
    boxes.push_back(readBox(boxIn));
  return boxes;
}

ShapeDesc readShape(const ObjectReader& in) {
  ShapeDesc shape;
  shape.kind = in.choice("type", shape.kind, kShapeNames);
  shape.center = in.vec3("center", shape.center);
  shape.halfExtents = in.vec3("half_extents", shape.halfExtents, kLength.hi);
  shape.radius = in.number("radius", shape.radius, kLength);
  shape.length = in.number("length", shape.length, kLength);
  shape.axis = in.vec3("axis", shape.axis);
  shape.capped = in.boolean("capped", shape.capped);
  shape.meshFile = in.string("file", shape.meshFile);
  shape.scale = in.number("scale", shape.scale, kScale);
  shape.solid = in.boolean("solid", shape.solid);
  shape.layers = in.integer("layers", shape.layers, 1, 8);
  return shape;
}

DeformableDesc readDeformable(const ObjectReader& in) {
  DeformableDesc d;
  d.stiffness = in.number("stiffness", d.stiffness, kNonNegative);
  d.damping = in.number("damping", d.damping, kNonNegative);
  d.breakingStrain = in.number("breaking_strain", d.breakingStrain, kNonNegative);
  d.springReach = in.number("spring_reach", d.springReach,
                            NumberRule{1, DeformableDesc::kMaxSpringReach, true, false});
  d.pinned = readBoxes(in, "pinned");
  d.cuts = readBoxes(in, "cuts");
  d.model = in.choice("model", d.model, kDeformableModelNames);
  d.substeps = in.integer("substeps", d.substeps, 1, 1000);
  d.bendingStiffness = in.number("bending_stiffness", d.bendingStiffness, kNonNegative);
  return d;
}

std::vector<ObjectDesc> readObjects(const ObjectReader& root) {
  std::vector<ObjectDesc> objects;
  for (const ObjectReader& in : root.objectArray("objects", /*required=*/false,
                                                 /*nonEmpty=*/false)) {
    ObjectDesc o;
    o.name = in.string("name", "object" + std::to_string(objects.size()));
    o.motion = in.choice("motion", o.motion, kMotionNames);
    o.shape = readShape(in.requiredObject("shape"));
    o.density = in.number("density", o.density, kDensity);
    o.spacing = in.number("spacing", o.spacing, kNonNegative);
    if (o.spacing != 0.0 && !kSpacing.accepts(o.spacing))
      in.context().fail(in.keyPath("spacing"), "expected 0 (the fluid's) or " +
                                                   kSpacing.describe() + ", got " +
                                                   formatNumber(o.spacing));
    o.velocity = in.vec3("velocity", o.velocity, kLargestVelocity);
    o.angularVelocity = in.vec3("angular_velocity", o.angularVelocity, kLargestSpin);
    o.deformable = readDeformable(in.object("deformable"));
    for (const ObjectReader& key : in.objectArray("keyframes", false, false)) {
      KeyframeDesc k;
      k.time = key.number("time", k.time, kNonNegative);
      k.offset = key.vec3("offset", k.offset);
      k.rotation = key.vec3("rotation", k.rotation);
      o.keyframes.push_back(k);
    }
    objects.push_back(std::move(o));
  }
  return objects;
}

InteractionDesc readInteraction(const ObjectReader& in) {
  InteractionDesc i;
  i.coupling = in.choice("coupling", i.coupling, kCouplingNames);
  i.influenceRatio = in.number("influence_ratio", i.influenceRatio, NumberRule{1, 4, false, false});
  i.distanceExponent =
      in.number("distance_exponent", i.distanceExponent, NumberRule{0, 10, false, false});
  i.stiffness = in.optionalNumber("stiffness", kPositive);
  i.damping = in.optionalNumber("damping", kNonNegative);
  i.shear = in.optionalNumber("shear", kNonNegative);
  i.maxAcceleration = in.optionalNumber("max_acceleration", kPositive);
  i.cutAwareDamping = in.boolean("cut_aware_damping", i.cutAwareDamping);
  return i;
}

ObjectEngineDesc readObjectEngine(const ObjectReader& in) {
  ObjectEngineDesc e;
  e.type = in.choice("type", e.type, kObjectEngineNames);
  e.rate = in.number("rate", e.rate, NumberRule{0, 16, true, false});
  e.ownThread = in.boolean("own_thread", e.ownThread);
  return e;
}

// Object names are how fluid blocks refer to them: unique, and every reference resolves.
void checkWallNames(const ReadContext& context, const Scene& scene) {
  for (std::size_t i = 0; i < scene.walls.size(); ++i) {
    const std::string& name = scene.walls[i].name;
    if (name.empty()) context.fail(joinIndex("walls", i) + ".name", "expected a name, got \"\"");
    for (std::size_t j = 0; j < i; ++j) {
      if (scene.walls[j].name == name)
        context.fail(joinIndex("walls", i) + ".name", "expected a name no other wall has, got \"" +
                                                          name + "\" (also walls[" +
                                                          std::to_string(j) + "])");
    }
  }
}

void checkObjectNames(const ReadContext& context, const Scene& scene) {
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (scene.objects[i].name == scene.objects[j].name)
        context.fail(joinIndex("objects", i) + ".name",
                     "expected a name no other object has, got \"" + scene.objects[i].name +
                         "\" (also objects[" + std::to_string(j) + "])");
    }
  }
  for (std::size_t b = 0; b < scene.fluid.blocks.size(); ++b) {
    const std::string& name = scene.fluid.blocks[b].inside;
    if (name.empty()) continue;
    bool found = false;
    for (const ObjectDesc& o : scene.objects) found = found || o.name == name;
    if (!found) {
      std::string names;
      for (const ObjectDesc& o : scene.objects) names += (names.empty() ? "" : ", ") + o.name;
      context.fail(joinIndex("fluid.blocks", b) + ".inside", "expected the name of an object (" +
                                                                 (names.empty() ? "none" : names) +
                                                                 "), got \"" + name + "\"");
    }
  }
}

// Probes have names of their own (they head probes.csv's columns), read inside the domain, and
// a force probe names an object.
void checkProbes(const ReadContext& context, const Scene& scene) {
  checkNames(context, scene.probes, "probes", "probe");
  for (std::size_t i = 0; i < scene.probes.size(); ++i) {
    const ProbeDesc& p = scene.probes[i];
    const std::string path = joinIndex("probes", i);
    if (p.kind == ProbeKind::Point)
      checkPointInDomain(context, p.position, path + ".position", scene.domain.box);
    if (p.kind == ProbeKind::Level) {
      checkPointInDomain(context, p.from, path + ".from", scene.domain.box);
      checkPointInDomain(context, p.to, path + ".to", scene.domain.box);
      if (p.from[0] == p.to[0] && p.from[1] == p.to[1] && p.from[2] == p.to[2])
        context.fail(path + ".to",
                     "expected a point apart from " + path + ".from " + formatVec3(p.from) +
                         ", got the same point",
                     {path + ".from"});
    }
    if (p.kind == ProbeKind::Force && !p.wall.empty()) {
      if (!p.object.empty())
        context.fail(path + ".wall",
                     "expected an object or a wall, not both (object \"" + p.object + "\")",
                     {path + ".object"});
      bool found = false;
      for (const WallDesc& w : scene.walls) found = found || w.name == p.wall;
      if (!found) {
        std::string names;
        for (const WallDesc& w : scene.walls) names += (names.empty() ? "" : ", ") + w.name;
        context.fail(path + ".wall", "expected the name of a wall (" +
                                         (names.empty() ? "none" : names) + "), got \"" + p.wall +
                                         "\"");
      }
    } else if (p.kind == ProbeKind::Force) {
      bool found = false;
      for (const ObjectDesc& o : scene.objects) found = found || o.name == p.object;
      if (!found) {
        std::string names;
        for (const ObjectDesc& o : scene.objects) names += (names.empty() ? "" : ", ") + o.name;
        context.fail(path + ".object", "expected the name of an object (" +
                                           (names.empty() ? "none" : names) + "), got \"" +
                                           p.object + "\"");
      }
    }
  }
}

// Continuity density is the weakly compressible solver's, in the symmetric pressure form.
void checkDensityModel(const ReadContext& context, const Scene& scene) {
  if (scene.fluid.density != DensityModel::Continuity) return;
  if (scene.fluid.solver != FluidSolver::Wcsph)
    context.fail("fluid.density",
                 "expected \"summation\" with fluid.solver \"dfsph\" (\"continuity\" needs "
                 "fluid.solver \"wcsph\"), got \"continuity\"",
                 {"fluid.solver"});
  if (scene.fluid.pressureForm != PressureForm::Symmetric)
    context.fail("fluid.density",
                 "expected \"summation\" with fluid.pressure_form \"paper\" (\"continuity\" "
                 "needs \"symmetric\"), got \"continuity\"",
                 {"fluid.pressure_form"});
}

// A periodic axis must hold the kernel's support three times (the grid's cells then see each
// neighbour once, through one image) and a whole number of spacings (the lattice then meets
// itself across the face). Objects are not carried across a periodic face.
void checkPeriodic(const ReadContext& context, const Scene& scene) {
  const DomainDesc& d = scene.domain;
  const double spacing = scene.fluid.spacing, support = scene.fluid.supportRatio * spacing;
  for (int a = 0; a < 3; ++a) {
    if (!d.periodic[a]) continue;
    const std::string axis(1, "xyz"[a]);
    const double period = d.box.max[a] - d.box.min[a];
    if (period < 3.0 * support)
      context.fail("domain.periodic",
                   "expected the domain to be at least 3 support radii (" +
                       formatNumber(3.0 * support) + " m) long along periodic axis " + axis +
                       ", got " + formatNumber(period) + " m",
                   {"domain.min", "domain.max", "fluid.spacing", "fluid.support_ratio"});
    const double spacings = period / spacing;
    if (std::abs(spacings - std::round(spacings)) > 1e-6 * spacings)
      context.fail("domain.periodic",
                   "expected the domain's length along periodic axis " + axis +
                       " to be a whole number of fluid.spacing (" + formatNumber(spacing) +
                       " m), got " + formatNumber(period) + " m, " + formatNumber(spacings) +
                       " spacings",
                   {"domain.min", "domain.max", "fluid.spacing"});
  }
  if ((d.periodic[0] || d.periodic[1] || d.periodic[2]) && !scene.objects.empty())
    context.fail("domain.periodic",
                 "expected no periodic axes in a scene with objects (objects are not carried "
                 "across a periodic face), got \"" +
                     std::string(d.periodic[0] ? "x" : "") + (d.periodic[1] ? "y" : "") +
                     (d.periodic[2] ? "z" : "") + "\"",
                 {"objects"});
}

// Boundary coupling gives the objects the incompressible solver's pressure: there is none
// without it.
void checkCoupling(const ReadContext& context, const Scene& scene) {
  if (scene.interaction.coupling == ObjectCoupling::Boundary &&
      scene.fluid.solver != FluidSolver::Dfsph)
    context.fail("interaction.coupling",
                 "expected \"contact\" with fluid.solver \"wcsph\" (\"boundary\" needs "
                 "fluid.solver \"dfsph\"), got \"boundary\"");
}

CalibrationDesc readCalibration(const ObjectReader& in) {
  CalibrationDesc calibration;
  calibration.mass = in.optionalNumber("mass", kPositive);
  calibration.maxExpectedSpeed = in.optionalNumber("max_expected_speed", kSpeed);
  calibration.speedOfSound = in.optionalNumber("speed_of_sound", NumberRule{0, 1e5, true, false});
  calibration.stiffness = in.optionalNumber("stiffness", kPositive);
  return calibration;
}

TimeDesc readTime(const ObjectReader& in) {
  TimeDesc time;
  time.duration = in.number("duration", time.duration, kDuration);
  time.cfl = in.number("cfl", time.cfl, kUnitStep);
  time.forceFactor = in.number("force_factor", time.forceFactor, kUnitStep);
  time.viscousFactor = in.number("viscous_factor", time.viscousFactor, kUnitStep);
  time.maxDt = in.number("max_dt", time.maxDt, kTimeStep);
  time.fixedDt = in.optionalNumber("fixed_dt", kTimeStep);
  return time;
}

OutputDesc readOutput(const ObjectReader& in) {
  OutputDesc output;
  output.fps = in.number("fps", output.fps, kFrameRate);
  output.format = in.choice("format", output.format, kFormatNames);
  output.probeRate = in.number("probe_rate", output.probeRate, kSampleRate);
  return output;
}

std::vector<ProbeDesc> readProbes(const ObjectReader& root) {
  std::vector<ProbeDesc> probes;
  for (const ObjectReader& in : root.objectArray("probes", /*required=*/false,
                                                 /*nonEmpty=*/false)) {
    ProbeDesc p;
    p.name = in.string("name", "probe" + std::to_string(probes.size()));
    p.kind = in.choice("type", p.kind, kProbeKindNames);
    if (p.kind == ProbeKind::Point) p.position = in.requiredVec3("position");
    if (p.kind == ProbeKind::Level) {
      p.from = in.requiredVec3("from");
      p.to = in.requiredVec3("to");
    }
    if (p.kind == ProbeKind::Force) {
      p.object = in.string("object", "");
      p.wall = in.string("wall", "");
    }
    probes.push_back(std::move(p));
  }
  return probes;
}

FailureDesc readFailure(const ObjectReader& in) {
  FailureDesc failure;
  failure.maxDensityError = in.number("max_density_error", failure.maxDensityError, kPositive);
  return failure;
}

LimitsDesc readLimits(const ObjectReader& in) {
  LimitsDesc limits;
  limits.maxParticles = in.number("max_particles", limits.maxParticles, kNonNegative);
  limits.maxMemoryGb = in.number("max_memory_gb", limits.maxMemoryGb, kNonNegative);
  return limits;
}

void checkWall(const ReadContext& context, const WallDesc& w, const std::string& path,
               const Scene& scene) {
  const double spacing = scene.fluid.spacing;
  switch (w.kind) {
    case WallKind::Tank:  // the box is the fluid's faces; the particle layers lie beyond it
    case WallKind::Box:
      checkBoxOrder(context, w.box, path);
      checkInsideDomain(context, w.box, path, scene.domain.box);
      break;
    case WallKind::Sphere:
      checkPointInDomain(context, w.center, joinKey(path, "center"), scene.domain.box);
      checkAtLeastSpacing(context, w.radius, joinKey(path, "radius"), spacing);
      break;
    case WallKind::Cylinder:
      checkPointInDomain(context, w.center, joinKey(path, "center"), scene.domain.box);
      checkAtLeastSpacing(context, w.radius, joinKey(path, "radius"), spacing);
      checkAtLeastSpacing(context, w.length, joinKey(path, "length"), 2.0 * spacing);
      if (!(lengthOf(w.axis) > 0.0) || !std::isfinite(lengthOf(w.axis)))
        context.fail(joinKey(path, "axis"), "expected a direction, got " + formatVec3(w.axis));
      break;
    case WallKind::Plane:
      checkPointInDomain(context, w.corner, joinKey(path, "corner"), scene.domain.box);
      checkAtLeastSpacing(context, lengthOf(w.edge1), joinKey(path, "edge1"), spacing);
      checkAtLeastSpacing(context, lengthOf(w.edge2), joinKey(path, "edge2"), spacing);
      checkNotParallel(context, w.edge1, w.edge2, joinKey(path, "edge1"), joinKey(path, "edge2"));
      break;
    case WallKind::Mesh:
      break;  // the file is read, and checked, as the walls are built
  }
}

void checkGeometry(const ReadContext& context, const Scene& scene) {
  checkBoxOrder(context, scene.domain.box, "domain");
  for (std::size_t i = 0; i < scene.fluid.blocks.size(); ++i) {
    const std::string path = joinIndex("fluid.blocks", i);
    checkBoxOrder(context, scene.fluid.blocks[i].box, path);
    checkInsideDomain(context, scene.fluid.blocks[i].box, path, scene.domain.box);
  }
  for (std::size_t i = 0; i < scene.walls.size(); ++i)
    checkWall(context, scene.walls[i], joinIndex("walls", i), scene);
}

}  // namespace

Scene parseScene(const json& document, const std::string& sourceName,
                 const std::vector<std::string>& overrides) {
  if (!document.is_object()) {
    throw InputError(sourceName + ": expected a JSON object at the top level, got " +
                     describeValue(document));
  }
  checkJsonDepth(document, sourceName);  // before anything copies or prints it
  json resolved = document;
  std::vector<AppliedOverride> applied = applyOverrides(resolved, overrides, sourceName);
  checkJsonDepth(resolved, sourceName);
  const ReadContext context(sourceName, std::move(applied));
  const ObjectReader root(context, &resolved, "", sceneSchema());

  Scene scene;
  scene.sourcePath = sourceName;
  scene.name = root.string("name", scene.name);
  // The name is the default output folder under out/: one plain path component.
  if (scene.name == "." || scene.name == ".." ||
      scene.name.find_first_of("/\\") != std::string::npos)
    context.fail("name", "expected a name without '/' or '\\' that is not '.' or '..', got \"" +
                             scene.name + "\"");
  scene.description = root.string("description", scene.description);
  scene.domain = readDomain(root.requiredObject("domain"));
  scene.gravity = root.vec3("gravity", scene.gravity, kLargestAcceleration);
  scene.fluid = readFluid(root.requiredObject("fluid"));
  scene.walls = readWalls(root);
  scene.objects = readObjects(root);
  scene.interaction = readInteraction(root.object("interaction"));
  scene.objectEngine = readObjectEngine(root.object("object_engine"));
  scene.calibration = readCalibration(root.object("calibration"));
  scene.time = readTime(root.object("time"));
  scene.output = readOutput(root.object("output"));
  scene.probes = readProbes(root);
  scene.emitters = readEmitters(root);
  scene.outlets = readOutlets(root);
  scene.failure = readFailure(root.object("failure"));
  scene.limits = readLimits(root.object("limits"));
  checkGeometry(context, scene);
  checkObjectNames(context, scene);
  checkWallNames(context, scene);
  checkCoupling(context, scene);
  checkPeriodic(context, scene);
  checkDensityModel(context, scene);
  checkProbes(context, scene);
  checkFlow(context, scene);
  return scene;
}

Scene loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  const std::string name = file.string();
  std::error_code error;
  if (!std::filesystem::exists(file, error)) {
    throw InputError(name + ": cannot read the scene file: it does not exist");
  }
  if (std::filesystem::is_directory(file, error)) {
    throw InputError(name + ": cannot read the scene file: it is a directory");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(name + ": cannot open the scene file for reading");
  return parseScene(parseJson(in, name), name, overrides);
}

}  // namespace sph::io
