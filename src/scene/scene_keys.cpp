// Every key of a scene file, declared once (scene_keys.hpp says how). The order is the order
// they are read and checked in; README.md's scene reference documents them and
// tests/scene/scene_schema_test.cpp holds the two to the same keys and defaults.
#include "scene/scene_keys.hpp"

#include <algorithm>

#include "sph/error.hpp"

namespace sph::scene {
namespace {

using nlohmann::json;

constexpr NumberRule kSupportRatio{1, 4, false, false};
constexpr NumberRule kDiffusion{0, 1, false, false};  // δ; 0.1 is the usual
constexpr double kWaterViscosity = 0.001;             // Pa·s, at 20 °C

template <class Desc>
auto is(ProbeKind kind) {
  return [kind](const Desc& d) { return d.kind == kind; };
}

// The scene's name is the default output folder under out/: one plain path component.
SceneKey<Scene> sceneName() {
  return custom<Scene>(
      "name",
      [](const ObjectReader& in, Scene& s) {
        s.name = in.string("name", s.name);
        if (s.name == "." || s.name == ".." || s.name.find_first_of("/\\") != std::string::npos)
          in.context().fail("name",
                            "expected a name without '/' or '\\' that is not '.' or '..', got \"" +
                                s.name + "\"");
      },
      [](const Scene& s) { return json(s.name); });
}

const SceneKeys<DomainDesc>& domainKeys() {
  static const SceneKeys<DomainDesc> keys{{
      boxMin(at(&DomainDesc::box)),
      boxMax(at(&DomainDesc::box)),
      choice("outside", at(&DomainDesc::outside), kOutsideNames),
      boolean("damped_box", at(&DomainDesc::dampedBox)),
      number("damping", at(&DomainDesc::damping), kClosedUnit),
      custom<DomainDesc>(
          "periodic",
          [](const ObjectReader& in, DomainDesc& d) {
            const std::string axes = in.string("periodic", "");
            for (char axis : axes) {
              const std::size_t a = std::string("xyz").find(axis);
              if (a == std::string::npos || d.periodic[a])
                in.context().fail(in.keyPath("periodic"),
                                  "expected the periodic axes as letters x, y and z, each at "
                                  "most once (\"xz\"; \"\" for none), got \"" +
                                      axes + "\"");
              d.periodic[a] = true;
            }
          },
          [](const DomainDesc& d) {
            std::string axes;
            for (int a = 0; a < 3; ++a)
              if (d.periodic[a]) axes += "xyz"[a];
            return json(axes);
          }),
  }};
  return keys;
}

const SceneKeys<DfsphDesc>& dfsphKeys() {
  static const SceneKeys<DfsphDesc> keys{{
      number("density_tolerance", at(&DfsphDesc::densityTolerance), kOpenUnit),
      number("divergence_tolerance", at(&DfsphDesc::divergenceTolerance), kOpenUnit),
      integer("min_iterations", at(&DfsphDesc::minIterations), 0, 1000),
      // No fewer than the minimum: the range the message states says so.
      custom<DfsphDesc>(
          "max_iterations",
          [](const ObjectReader& in, DfsphDesc& d) {
            d.maxIterations =
                in.integer("max_iterations", std::max(d.maxIterations, d.minIterations),
                           std::max(d.minIterations, 1), 10000);
          },
          [](const DfsphDesc& d) { return json(d.maxIterations); }),
      boolean("warm_start", at(&DfsphDesc::warmStart)),
      boolean("divergence_solve", at(&DfsphDesc::divergenceSolve)),
      boolean("density_solve", at(&DfsphDesc::densitySolve)),
      number("force_factor", at(&DfsphDesc::forceFactor), kUnitStep),
      number("coarse_correction", at(&DfsphDesc::coarseCorrection), kClosedUnit),
  }};
  return keys;
}

const SceneKeys<PbfDesc>& pbfKeys() {
  static const SceneKeys<PbfDesc> keys{{
      integer("iterations", at(&PbfDesc::iterations), 1, 1000),
      number("relaxation", at(&PbfDesc::relaxation), kNonNegative),
      number("tensile_strength", at(&PbfDesc::tensileStrength), kNonNegative),
      number("tensile_distance", at(&PbfDesc::tensileDistance), kOpenUnit),
      number("xsph", at(&PbfDesc::xsph), kClosedUnit),
  }};
  return keys;
}

const SceneKeys<FluidDesc>& viscosityKeys() {
  static const SceneKeys<FluidDesc> keys{{
      choice("model", at(&FluidDesc::viscosityModel), kViscosityNames),
      // Müller's μ is in Pa·s: its default is water's, not the artificial α's.
      custom<FluidDesc>(
          "value",
          [](const ObjectReader& in, FluidDesc& f) {
            const bool muller = f.viscosityModel == ViscosityModel::Muller;
            f.viscosity = in.number("value", muller ? kWaterViscosity : f.viscosity, kNonNegative);
          },
          [](const FluidDesc& f) { return json(f.viscosity); }),
      number("wall_friction", at(&FluidDesc::wallFriction), kNonNegative),
  }};
  return keys;
}

const SceneKeys<FluidDesc>& surfaceTensionKeys() {
  static const SceneKeys<FluidDesc> keys{{
      number("coefficient", at(&FluidDesc::surfaceTension), kSurfaceTension),
      optionalNumber("threshold", at(&FluidDesc::surfaceThreshold), kPositive),
  }};
  return keys;
}

const SceneKeys<FluidBlock>& blockKeys() {
  static const SceneKeys<FluidBlock> keys{{
      boxMin(at(&FluidBlock::box)),
      boxMax(at(&FluidBlock::box)),
      vec3("velocity", at(&FluidBlock::velocity), kLargestVelocity),
      boolean("hydrostatic", at(&FluidBlock::hydrostatic)),
      text("inside", at(&FluidBlock::inside)),
      vec3("angular_velocity", at(&FluidBlock::angularVelocity), kLargestSpin),
  }};
  return keys;
}

const SceneKeys<FluidDesc>& fluidKeys() {
  static const SceneKeys<FluidDesc> keys{{
      number("rest_density", at(&FluidDesc::restDensity), kDensity),
      number("spacing", at(&FluidDesc::spacing), kSpacing),
      number("support_ratio", at(&FluidDesc::supportRatio), kSupportRatio),
      choice("solver", at(&FluidDesc::solver), kSolverNames),
      section("dfsph", at(&FluidDesc::dfsph), dfsphKeys()),
      section("pbf", at(&FluidDesc::pbf), pbfKeys()),
      choice("kernel", at(&FluidDesc::kernel), kKernelNames),
      choice("eos", at(&FluidDesc::eos), kEosNames),
      boolean("clamp_negative_pressure", at(&FluidDesc::clampNegativePressure)),
      choice("pressure_form", at(&FluidDesc::pressureForm), kPressureFormNames),
      choice("density", at(&FluidDesc::density), kDensityModelNames),
      number("density_diffusion", at(&FluidDesc::densityDiffusion), kDiffusion),
      group("viscosity", viscosityKeys()),
      group("surface_tension", surfaceTensionKeys()),
      list("blocks", at(&FluidDesc::blocks), blockKeys(), /*required=*/true, /*nonEmpty=*/true),
  }};
  return keys;
}

// A wall's keys depend on its type; those of another type are refused. The order lists each
// type's keys in the order its refusal names them.
const SceneKeys<WallDesc>& wallKeys() {
  using K = WallKind;
  auto only = [](std::initializer_list<WallKind> kinds) {
    const std::vector<WallKind> list(kinds);
    return [list](const WallDesc& w) {
      return std::find(list.begin(), list.end(), w.kind) != list.end();
    };
  };
  static const SceneKeys<WallDesc> keys{
      {
          text("name", at(&WallDesc::name)),
          choice("type", at(&WallDesc::kind), kWallKindNames),
          integer("layers", at(&WallDesc::layers), 1, 4),
          boxMin(at(&WallDesc::box)).only(only({K::Tank, K::Box})),
          boxMax(at(&WallDesc::box)).only(only({K::Tank, K::Box})),
          boolean("closed", at(&WallDesc::closed)).only(only({K::Tank})),
          custom<WallDesc>(
              "file",
              [](const ObjectReader& in, WallDesc& w) {
                w.meshFile = in.string("file", w.meshFile);
                if (w.meshFile.empty())
                  in.context().fail(in.keyPath("file"), "expected the path of an OBJ or STL file");
              },
              [](const WallDesc& w) { return json(w.meshFile); },
              requiredSchema(valueSchema("file")))
              .only(only({K::Mesh})),
          requiredVec3("center", at(&WallDesc::center)).only(only({K::Sphere, K::Cylinder})),
          vec3("center", at(&WallDesc::center)).only(only({K::Mesh})),
          requiredNumber("radius", at(&WallDesc::radius), kPositive, "a length in m")
              .only(only({K::Sphere, K::Cylinder})),
          requiredNumber("length", at(&WallDesc::length), kPositive, "a length in m")
              .only(only({K::Cylinder})),
          vec3("axis", at(&WallDesc::axis)).only(only({K::Cylinder})),
          boolean("capped", at(&WallDesc::capped)).only(only({K::Cylinder})),
          choice("fluid", at(&WallDesc::fluid), kFluidSideNames)
              .only(only({K::Box, K::Sphere, K::Cylinder})),
          requiredVec3("corner", at(&WallDesc::corner)).only(only({K::Plane})),
          requiredVec3("edge1", at(&WallDesc::edge1)).only(only({K::Plane})),
          requiredVec3("edge2", at(&WallDesc::edge2)).only(only({K::Plane})),
          number("scale", at(&WallDesc::scale), kScale).only(only({K::Mesh})),
          boolean("open", at(&WallDesc::open)).only(only({K::Mesh})),
      },
      [](const WallDesc& w) { return std::string(nameOf(w.kind, kWallKindNames)) + " wall"; }};
  return keys;
}

const SceneKeys<ShapeDesc>& shapeKeys() {
  static const SceneKeys<ShapeDesc> keys{{
      choice("type", at(&ShapeDesc::kind), kShapeNames),
      vec3("center", at(&ShapeDesc::center)),
      vec3("half_extents", at(&ShapeDesc::halfExtents), kLength.hi),
      number("radius", at(&ShapeDesc::radius), kLength),
      number("length", at(&ShapeDesc::length), kLength),
      vec3("axis", at(&ShapeDesc::axis)),
      boolean("capped", at(&ShapeDesc::capped)),
      text("file", at(&ShapeDesc::meshFile)),
      number("scale", at(&ShapeDesc::scale), kScale),
      boolean("solid", at(&ShapeDesc::solid)),
      integer("layers", at(&ShapeDesc::layers), 1, 8),
  }};
  return keys;
}

const SceneKeys<AxisBox>& boxKeys() {
  static const SceneKeys<AxisBox> keys{{
      requiredVec3("min", at(&AxisBox::min)),
      requiredVec3("max", at(&AxisBox::max)),
  }};
  return keys;
}

const SceneKeys<DeformableDesc>& deformableKeys() {
  static const SceneKeys<DeformableDesc> keys{{
      number("stiffness", at(&DeformableDesc::stiffness), kNonNegative),
      number("damping", at(&DeformableDesc::damping), kNonNegative),
      number("breaking_strain", at(&DeformableDesc::breakingStrain), kNonNegative),
      number("spring_reach", at(&DeformableDesc::springReach),
             NumberRule{1, DeformableDesc::kMaxSpringReach, true, false}),
      list("pinned", at(&DeformableDesc::pinned), boxKeys()),
      list("cuts", at(&DeformableDesc::cuts), boxKeys()),
      choice("model", at(&DeformableDesc::model), kDeformableModelNames),
      integer("substeps", at(&DeformableDesc::substeps), 1, 1000),
      number("bending_stiffness", at(&DeformableDesc::bendingStiffness), kNonNegative),
  }};
  return keys;
}

const SceneKeys<KeyframeDesc>& keyframeKeys() {
  static const SceneKeys<KeyframeDesc> keys{{
      number("time", at(&KeyframeDesc::time), kNonNegative),
      vec3("offset", at(&KeyframeDesc::offset)),
      vec3("rotation", at(&KeyframeDesc::rotation)),
  }};
  return keys;
}

const SceneKeys<ObjectDesc>& objectKeys() {
  static const SceneKeys<ObjectDesc> keys{{
      text("name", at(&ObjectDesc::name)),
      choice("motion", at(&ObjectDesc::motion), kMotionNames),
      section("shape", at(&ObjectDesc::shape), shapeKeys(), /*required=*/true),
      number("density", at(&ObjectDesc::density), kDensity),
      custom<ObjectDesc>(
          "spacing",
          [](const ObjectReader& in, ObjectDesc& o) {
            o.spacing = in.number("spacing", o.spacing, kNonNegative);
            if (o.spacing != 0.0 && !kSpacing.accepts(o.spacing))
              in.context().fail(in.keyPath("spacing"), "expected 0 (the fluid's) or " +
                                                           kSpacing.describe() + ", got " +
                                                           formatNumber(o.spacing));
          },
          [](const ObjectDesc& o) { return json(o.spacing); }),
      vec3("velocity", at(&ObjectDesc::velocity), kLargestVelocity),
      vec3("angular_velocity", at(&ObjectDesc::angularVelocity), kLargestSpin),
      section("deformable", at(&ObjectDesc::deformable), deformableKeys()),
      list("keyframes", at(&ObjectDesc::keyframes), keyframeKeys()),
  }};
  return keys;
}

const SceneKeys<InteractionDesc>& interactionKeys() {
  static const SceneKeys<InteractionDesc> keys{{
      choice("coupling", at(&InteractionDesc::coupling), kCouplingNames),
      number("influence_ratio", at(&InteractionDesc::influenceRatio),
             NumberRule{1, 4, false, false}),
      number("distance_exponent", at(&InteractionDesc::distanceExponent),
             NumberRule{0, 10, false, false}),
      optionalNumber("stiffness", at(&InteractionDesc::stiffness), kPositive),
      optionalNumber("damping", at(&InteractionDesc::damping), kNonNegative),
      optionalNumber("shear", at(&InteractionDesc::shear), kNonNegative),
      optionalNumber("max_acceleration", at(&InteractionDesc::maxAcceleration), kPositive),
      boolean("cut_aware_damping", at(&InteractionDesc::cutAwareDamping)),
  }};
  return keys;
}

const SceneKeys<ObjectEngineDesc>& objectEngineKeys() {
  static const SceneKeys<ObjectEngineDesc> keys{{
      choice("type", at(&ObjectEngineDesc::type), kObjectEngineNames),
      number("rate", at(&ObjectEngineDesc::rate), NumberRule{0, 16, true, false}),
      boolean("own_thread", at(&ObjectEngineDesc::ownThread)),
  }};
  return keys;
}

const SceneKeys<CalibrationDesc>& calibrationKeys() {
  static const SceneKeys<CalibrationDesc> keys{{
      optionalNumber("mass", at(&CalibrationDesc::mass), kPositive),
      optionalNumber("max_expected_speed", at(&CalibrationDesc::maxExpectedSpeed), kSpeed),
      optionalNumber("speed_of_sound", at(&CalibrationDesc::speedOfSound),
                     NumberRule{0, 1e5, true, false}),
      optionalNumber("stiffness", at(&CalibrationDesc::stiffness), kPositive),
  }};
  return keys;
}

const SceneKeys<TimeDesc>& timeKeys() {
  static const SceneKeys<TimeDesc> keys{{
      number("duration", at(&TimeDesc::duration), kDuration),
      number("cfl", at(&TimeDesc::cfl), kUnitStep),
      number("force_factor", at(&TimeDesc::forceFactor), kUnitStep),
      number("viscous_factor", at(&TimeDesc::viscousFactor), kUnitStep),
      number("max_dt", at(&TimeDesc::maxDt), kTimeStep),
      optionalNumber("fixed_dt", at(&TimeDesc::fixedDt), kTimeStep),
      number("frame_dt", at(&TimeDesc::frameDt), kTimeStep),
      integer("substeps", at(&TimeDesc::substeps), 0, 100000),
  }};
  return keys;
}

const SceneKeys<OutputDesc>& outputKeys() {
  static const SceneKeys<OutputDesc> keys{{
      number("fps", at(&OutputDesc::fps), kFrameRate),
      choice("format", at(&OutputDesc::format), kFormatNames),
      number("probe_rate", at(&OutputDesc::probeRate), kSampleRate),
  }};
  return keys;
}

// Past 1e6 /m a layer a micron thick is opaque: nothing a scene's spacing resolves.
const SceneKeys<RenderDesc>& renderKeys() {
  static const SceneKeys<RenderDesc> keys{{
      choice("look", at(&RenderDesc::look), kLookNames),
      vec3Within("colour", at(&RenderDesc::colour), 0.0, 1.0),
      vec3Within("absorption", at(&RenderDesc::absorption), 0.0, 1e6),
  }};
  return keys;
}

const SceneKeys<ProbeDesc>& probeKeys() {
  static const SceneKeys<ProbeDesc> keys{
      {
          text("name", at(&ProbeDesc::name)),
          choice("type", at(&ProbeDesc::kind), kProbeKindNames),
          requiredVec3("position", at(&ProbeDesc::position)).only(is<ProbeDesc>(ProbeKind::Point)),
          requiredVec3("from", at(&ProbeDesc::from)).only(is<ProbeDesc>(ProbeKind::Level)),
          requiredVec3("to", at(&ProbeDesc::to)).only(is<ProbeDesc>(ProbeKind::Level)),
          text("object", at(&ProbeDesc::object)).only(is<ProbeDesc>(ProbeKind::Force)),
          text("wall", at(&ProbeDesc::wall)).only(is<ProbeDesc>(ProbeKind::Force)),
      },
      [](const ProbeDesc& p) { return std::string(nameOf(p.kind, kProbeKindNames)) + " probe"; }};
  return keys;
}

// An emitter's keys depend on its shape; those of the other shape are refused.
const SceneKeys<EmitterDesc>& emitterKeys() {
  const auto disc = [](const EmitterDesc& e) { return e.shape == EmitterShape::Disc; };
  const auto rectangle = [](const EmitterDesc& e) { return e.shape == EmitterShape::Rectangle; };
  static const SceneKeys<EmitterDesc> keys{
      {
          text("name", at(&EmitterDesc::name)),
          choice("shape", at(&EmitterDesc::shape), kEmitterShapeNames),
          requiredNumber("speed", at(&EmitterDesc::speed), kSpeed, "a speed in m/s"),
          number("start", at(&EmitterDesc::start), kNonNegative),
          number("end", at(&EmitterDesc::end), kPositive),
          requiredVec3("center", at(&EmitterDesc::center)).only(disc),
          requiredNumber("radius", at(&EmitterDesc::radius), kPositive, "a length in m").only(disc),
          requiredVec3("direction", at(&EmitterDesc::direction)).only(disc),
          requiredVec3("corner", at(&EmitterDesc::corner)).only(rectangle),
          requiredVec3("edge1", at(&EmitterDesc::edge1)).only(rectangle),
          requiredVec3("edge2", at(&EmitterDesc::edge2)).only(rectangle),
      },
      [](const EmitterDesc& e) {
        return std::string(nameOf(e.shape, kEmitterShapeNames)) + " emitter";
      }};
  return keys;
}

const SceneKeys<OutletDesc>& outletKeys() {
  static const SceneKeys<OutletDesc> keys{{
      text("name", at(&OutletDesc::name)),
      boxMin(at(&OutletDesc::box)),
      boxMax(at(&OutletDesc::box)),
  }};
  return keys;
}

const SceneKeys<FailureDesc>& failureKeys() {
  static const SceneKeys<FailureDesc> keys{{
      number("max_density_error", at(&FailureDesc::maxDensityError), kPositive),
      optionalNumber("max_speed", at(&FailureDesc::maxSpeed), kSpeed),
  }};
  return keys;
}

const SceneKeys<LimitsDesc>& limitsKeys() {
  static const SceneKeys<LimitsDesc> keys{{
      number("max_particles", at(&LimitsDesc::maxParticles), kNonNegative),
      number("max_memory_gb", at(&LimitsDesc::maxMemoryGb), kNonNegative),
  }};
  return keys;
}

// What an unnamed element of a list is called: its kind and its place in the list.
constexpr const char* kWallName = "wall";
constexpr const char* kObjectName = "object";
constexpr const char* kProbeName = "probe";
constexpr const char* kEmitterName = "emitter";
constexpr const char* kOutletName = "outlet";

template <class Desc>
void nameElement(Desc& d, std::size_t index, const char* prefix) {
  d.name = prefix + std::to_string(index);
}

// The loader names each element before reading its keys: a name in the file replaces it.
template <class Desc>
std::function<void(Desc&, std::size_t)> namedAfter(const char* prefix) {
  return [prefix](Desc& d, std::size_t index) { nameElement(d, index, prefix); };
}

template <class Desc>
void nameUnnamed(std::vector<Desc>& items, const char* prefix) {
  for (std::size_t i = 0; i < items.size(); ++i)
    if (items[i].name.empty()) nameElement(items[i], i, prefix);
}

}  // namespace

void nameUnnamedElements(Scene& scene) {
  nameUnnamed(scene.walls, kWallName);
  nameUnnamed(scene.objects, kObjectName);
  nameUnnamed(scene.probes, kProbeName);
  nameUnnamed(scene.emitters, kEmitterName);
  nameUnnamed(scene.outlets, kOutletName);
}

const SceneKeys<Scene>& sceneKeys() {
  static const SceneKeys<Scene> keys{{
      sceneName(),
      text("description", at(&Scene::description)),
      section("domain", at(&Scene::domain), domainKeys(), /*required=*/true),
      vec3("gravity", at(&Scene::gravity), kLargestAcceleration),
      section("fluid", at(&Scene::fluid), fluidKeys(), /*required=*/true),
      list("walls", at(&Scene::walls), wallKeys(), false, false, namedAfter<WallDesc>(kWallName)),
      list("objects", at(&Scene::objects), objectKeys(), false, false,
           namedAfter<ObjectDesc>(kObjectName)),
      section("interaction", at(&Scene::interaction), interactionKeys()),
      section("object_engine", at(&Scene::objectEngine), objectEngineKeys()),
      section("calibration", at(&Scene::calibration), calibrationKeys()),
      section("time", at(&Scene::time), timeKeys()),
      section("output", at(&Scene::output), outputKeys()),
      list("probes", at(&Scene::probes), probeKeys(), false, false,
           namedAfter<ProbeDesc>(kProbeName)),
      list("emitters", at(&Scene::emitters), emitterKeys(), false, false,
           namedAfter<EmitterDesc>(kEmitterName)),
      list("outlets", at(&Scene::outlets), outletKeys(), false, false,
           namedAfter<OutletDesc>(kOutletName)),
      section("failure", at(&Scene::failure), failureKeys()),
      section("limits", at(&Scene::limits), limitsKeys()),
      section("render", at(&Scene::render), renderKeys()),
  }};
  return keys;
}

}  // namespace sph::scene
