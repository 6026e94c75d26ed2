// sceneToJson: the resolved scene in the scene-file schema, for summary.json and round trips.
#include <optional>

#include <nlohmann/json.hpp>

#include "io/scene_loader.hpp"
#include "io/scene_schema.hpp"

namespace sph::io {
namespace {

using nlohmann::json;

json toJson(const Vec3d& v) {
  return json::array({v[0], v[1], v[2]});
}

json toJson(const std::optional<double>& value) {
  return value ? json(*value) : json(nullptr);
}

json boxToJson(const AxisBox& box) {
  return {{"min", toJson(box.min)}, {"max", toJson(box.max)}};
}

json domainToJson(const DomainDesc& domain) {
  json out = boxToJson(domain.box);
  out["outside"] = nameOf(domain.outside, kOutsideNames);
  out["damped_box"] = domain.dampedBox;
  out["damping"] = domain.damping;
  std::string periodic;
  for (int a = 0; a < 3; ++a)
    if (domain.periodic[a]) periodic += "xyz"[a];
  out["periodic"] = periodic;
  return out;
}

json fluidToJson(const FluidDesc& fluid) {
  json blocks = json::array();
  for (const FluidBlock& block : fluid.blocks) {
    json b = boxToJson(block.box);
    b["velocity"] = toJson(block.velocity);
    b["hydrostatic"] = block.hydrostatic;
    b["inside"] = block.inside;  // "": in no object
    b["angular_velocity"] = toJson(block.angularVelocity);
    blocks.push_back(std::move(b));
  }
  return {
      {"rest_density", fluid.restDensity},
      {"spacing", fluid.spacing},
      {"support_ratio", fluid.supportRatio},
      {"solver", nameOf(fluid.solver, kSolverNames)},
      {"dfsph",
       {{"density_tolerance", fluid.dfsph.densityTolerance},
        {"divergence_tolerance", fluid.dfsph.divergenceTolerance},
        {"min_iterations", fluid.dfsph.minIterations},
        {"max_iterations", fluid.dfsph.maxIterations},
        {"warm_start", fluid.dfsph.warmStart},
        {"divergence_solve", fluid.dfsph.divergenceSolve},
        {"density_solve", fluid.dfsph.densitySolve},
        {"force_factor", fluid.dfsph.forceFactor}}},
      {"kernel", nameOf(fluid.kernel, kKernelNames)},
      {"eos", nameOf(fluid.eos, kEosNames)},
      {"clamp_negative_pressure", fluid.clampNegativePressure},
      {"pressure_form", nameOf(fluid.pressureForm, kPressureFormNames)},
      {"density", nameOf(fluid.density, kDensityModelNames)},
      {"density_diffusion", fluid.densityDiffusion},
      {"viscosity",
       {{"model", nameOf(fluid.viscosityModel, kViscosityNames)},
        {"value", fluid.viscosity},
        {"wall_friction", fluid.wallFriction}}},
      {"surface_tension",
       {{"coefficient", fluid.surfaceTension}, {"threshold", toJson(fluid.surfaceThreshold)}}},
      {"blocks", std::move(blocks)},
  };
}

json wallToJson(const WallDesc& wall) {
  json w = json::object();
  w["name"] = wall.name;
  w["type"] = nameOf(wall.kind, kWallKindNames);
  w["layers"] = wall.layers;
  const char* fluid = nameOf(wall.fluid, kFluidSideNames);
  switch (wall.kind) {
    case WallKind::Tank:
      w.update(boxToJson(wall.box));
      w["closed"] = wall.closed;
      break;
    case WallKind::Box:
      w.update(boxToJson(wall.box));
      w["fluid"] = fluid;
      break;
    case WallKind::Sphere:
      w.update({{"center", wall.center}, {"radius", wall.radius}, {"fluid", fluid}});
      break;
    case WallKind::Cylinder:
      w.update({{"center", wall.center},
                {"radius", wall.radius},
                {"length", wall.length},
                {"axis", wall.axis},
                {"capped", wall.capped},
                {"fluid", fluid}});
      break;
    case WallKind::Plane:
      w.update({{"corner", wall.corner}, {"edge1", wall.edge1}, {"edge2", wall.edge2}});
      break;
    case WallKind::Mesh:
      w.update({{"file", wall.meshFile},
                {"center", wall.center},
                {"scale", wall.scale},
                {"open", wall.open}});
      break;
  }
  return w;
}

json wallsToJson(const std::vector<WallDesc>& walls) {
  json out = json::array();
  for (const WallDesc& wall : walls) out.push_back(wallToJson(wall));
  return out;
}

json boxesToJson(const std::vector<AxisBox>& boxes) {
  json out = json::array();
  for (const AxisBox& box : boxes) out.push_back(boxToJson(box));
  return out;
}

json objectToJson(const ObjectDesc& o) {
  const ShapeDesc& s = o.shape;
  json keyframes = json::array();
  for (const KeyframeDesc& k : o.keyframes)
    keyframes.push_back(
        {{"time", k.time}, {"offset", toJson(k.offset)}, {"rotation", toJson(k.rotation)}});
  const DeformableDesc& d = o.deformable;
  return {{"name", o.name},
          {"motion", nameOf(o.motion, kMotionNames)},
          {"shape",
           {{"type", nameOf(s.kind, kShapeNames)},
            {"center", toJson(s.center)},
            {"half_extents", toJson(s.halfExtents)},
            {"radius", s.radius},
            {"length", s.length},
            {"axis", toJson(s.axis)},
            {"capped", s.capped},
            {"file", s.meshFile},
            {"scale", s.scale},
            {"solid", s.solid},
            {"layers", s.layers}}},
          {"density", o.density},
          {"spacing", o.spacing},
          {"velocity", toJson(o.velocity)},
          {"angular_velocity", toJson(o.angularVelocity)},
          {"deformable",
           {{"stiffness", d.stiffness},
            {"damping", d.damping},
            {"breaking_strain", d.breakingStrain},
            {"spring_reach", d.springReach},
            {"pinned", boxesToJson(d.pinned)},
            {"cuts", boxesToJson(d.cuts)},
            {"model", nameOf(d.model, kDeformableModelNames)},
            {"substeps", d.substeps},
            {"bending_stiffness", d.bendingStiffness}}},
          {"keyframes", std::move(keyframes)}};
}

json interactionToJson(const InteractionDesc& i) {
  return {{"coupling", nameOf(i.coupling, kCouplingNames)},
          {"influence_ratio", i.influenceRatio},
          {"distance_exponent", i.distanceExponent},
          {"stiffness", toJson(i.stiffness)},
          {"damping", toJson(i.damping)},
          {"shear", toJson(i.shear)},
          {"max_acceleration", toJson(i.maxAcceleration)},
          {"cut_aware_damping", i.cutAwareDamping}};
}

// Every key, also those its type does not read (as for an object's shape).
json probeToJson(const ProbeDesc& p) {
  return {{"name", p.name},
          {"type", nameOf(p.kind, kProbeKindNames)},
          {"position", toJson(p.position)},
          {"from", toJson(p.from)},
          {"to", toJson(p.to)},
          {"object", p.object},
          {"wall", p.wall}};
}

// Only the keys of the emitter's shape: the loader refuses the other shape's.
json emitterToJson(const EmitterDesc& e) {
  json out = {{"name", e.name},
              {"shape", nameOf(e.shape, kEmitterShapeNames)},
              {"speed", e.speed},
              {"start", e.start},
              {"end", e.end}};
  if (e.shape == EmitterShape::Disc) {
    out["center"] = toJson(e.center);
    out["radius"] = e.radius;
    out["direction"] = toJson(e.direction);
  } else {
    out["corner"] = toJson(e.corner);
    out["edge1"] = toJson(e.edge1);
    out["edge2"] = toJson(e.edge2);
  }
  return out;
}

}  // namespace

json sceneToJson(const Scene& scene) {
  const CalibrationDesc& calibration = scene.calibration;
  const TimeDesc& time = scene.time;
  return {
      {"name", scene.name},
      {"description", scene.description},
      {"domain", domainToJson(scene.domain)},
      {"gravity", toJson(scene.gravity)},
      {"fluid", fluidToJson(scene.fluid)},
      {"walls", wallsToJson(scene.walls)},
      {"objects",
       [&] {
         json out = json::array();
         for (const ObjectDesc& o : scene.objects) out.push_back(objectToJson(o));
         return out;
       }()},
      {"interaction", interactionToJson(scene.interaction)},
      {"object_engine",
       {{"type", nameOf(scene.objectEngine.type, kObjectEngineNames)},
        {"rate", scene.objectEngine.rate},
        {"own_thread", scene.objectEngine.ownThread}}},
      {"calibration",
       {{"mass", toJson(calibration.mass)},
        {"max_expected_speed", toJson(calibration.maxExpectedSpeed)},
        {"speed_of_sound", toJson(calibration.speedOfSound)},
        {"stiffness", toJson(calibration.stiffness)}}},
      {"time",
       {{"duration", time.duration},
        {"cfl", time.cfl},
        {"force_factor", time.forceFactor},
        {"viscous_factor", time.viscousFactor},
        {"max_dt", time.maxDt},
        {"fixed_dt", toJson(time.fixedDt)}}},
      {"output",
       {{"fps", scene.output.fps},
        {"format", nameOf(scene.output.format, kFormatNames)},
        {"probe_rate", scene.output.probeRate}}},
      {"probes",
       [&] {
         json out = json::array();
         for (const ProbeDesc& p : scene.probes) out.push_back(probeToJson(p));
         return out;
       }()},
      {"emitters",
       [&] {
         json out = json::array();
         for (const EmitterDesc& e : scene.emitters) out.push_back(emitterToJson(e));
         return out;
       }()},
      {"outlets",
       [&] {
         json out = json::array();
         for (const OutletDesc& o : scene.outlets)
           out.push_back(
               {{"name", o.name}, {"min", toJson(o.box.min)}, {"max", toJson(o.box.max)}});
         return out;
       }()},
      {"failure", {{"max_density_error", scene.failure.maxDensityError}}},
      {"limits",
       {{"max_particles", scene.limits.maxParticles}, {"max_memory_gb", scene.limits.maxMemoryGb}}},
  };
}

}  // namespace sph::io
