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
  return out;
}

json fluidToJson(const FluidDesc& fluid) {
  json blocks = json::array();
  for (const FluidBlock& block : fluid.blocks) {
    json b = boxToJson(block.box);
    b["velocity"] = toJson(block.velocity);
    b["hydrostatic"] = block.hydrostatic;
    blocks.push_back(std::move(b));
  }
  return {
      {"rest_density", fluid.restDensity},
      {"spacing", fluid.spacing},
      {"support_ratio", fluid.supportRatio},
      {"kernel", nameOf(fluid.kernel, kKernelNames)},
      {"eos", nameOf(fluid.eos, kEosNames)},
      {"clamp_negative_pressure", fluid.clampNegativePressure},
      {"pressure_form", nameOf(fluid.pressureForm, kPressureFormNames)},
      {"viscosity",
       {{"model", nameOf(fluid.viscosityModel, kViscosityNames)},
        {"value", fluid.viscosity},
        {"wall_friction", fluid.wallFriction}}},
      {"surface_tension",
       {{"coefficient", fluid.surfaceTension}, {"threshold", toJson(fluid.surfaceThreshold)}}},
      {"blocks", std::move(blocks)},
  };
}

json wallsToJson(const std::vector<WallTank>& walls) {
  json out = json::array();
  for (const WallTank& wall : walls) {
    json w = boxToJson(wall.box);
    w["type"] = nameOf(WallType::Tank, kWallTypeNames);
    w["layers"] = wall.layers;
    w["closed"] = wall.closed;
    out.push_back(std::move(w));
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
       {{"fps", scene.output.fps}, {"format", nameOf(scene.output.format, kFormatNames)}}},
      {"failure", {{"max_density_error", scene.failure.maxDensityError}}},
  };
}

}  // namespace sph::io
