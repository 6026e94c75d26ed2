// Scene documents and helpers shared by the scene loader tests.
#pragma once

#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/scene_loader.hpp"
#include "sph/error.hpp"
#include "sph/scene.hpp"

namespace sph::io::scene_test {

inline constexpr const char* kSource = "scenes/x.json";

// The smallest valid scene: the two required keys.
inline nlohmann::json minimalSceneJson() {
  return nlohmann::json::parse(R"({
    "domain": {"min": [0, 0, 0], "max": [1, 1, 1]},
    "fluid": {"blocks": [{"min": [0, 0, 0], "max": [0.5, 0.5, 0.5]}]}
  })");
}

// Every key, each set to a value other than its default.
inline nlohmann::json completeSceneJson() {
  return nlohmann::json::parse(R"({
    "name": "dam_break",
    "description": "A column of water collapses.",
    "domain": {"min": [-0.1, 0, -0.2], "max": [1.5, 1.2, 0.3], "outside": "clamp",
               "damped_box": true, "damping": 0.3},
    "gravity": [0, -3.7, 0.5],
    "fluid": {
      "rest_density": 998.2, "spacing": 0.02, "support_ratio": 2.5,
      "solver": "dfsph",
      "dfsph": {"density_tolerance": 0.001, "divergence_tolerance": 0.002, "min_iterations": 2,
                "max_iterations": 50, "warm_start": false, "divergence_solve": false,
                "density_solve": false, "force_factor": 0.05},
      "kernel": "wendland_c2", "eos": "tait", "clamp_negative_pressure": false,
      "pressure_form": "paper",
      "viscosity": {"model": "muller", "value": 0.05, "wall_friction": 0.4},
      "surface_tension": {"coefficient": 0.0728, "threshold": 6.5},
      "blocks": [
        {"min": [0, 0, -0.1], "max": [0.4, 0.6, 0.2], "velocity": [1, 0, -0.25],
         "angular_velocity": [0, 2, 0]},
        {"min": [1, 0, 0], "max": [1.2, 0.1, 0.1]}
      ]
    },
    "walls": [{"type": "tank", "min": [0, 0, -0.15], "max": [1.4, 1.0, 0.25], "layers": 3,
               "closed": true},
              {"name": "crate", "type": "box", "min": [0.6, 0, -0.05], "max": [0.7, 0.1, 0.05],
               "fluid": "inside",
               "layers": 1},
              {"type": "sphere", "center": [0.3, 0.5, 0], "radius": 0.1, "fluid": "inside"},
              {"type": "cylinder", "center": [1, 0.5, 0], "radius": 0.05, "length": 0.3,
               "axis": [1, 0, 0], "capped": false, "fluid": "inside", "layers": 4},
              {"type": "plane", "corner": [0.8, 0, -0.1], "edge1": [0.3, 0.2, 0],
               "edge2": [0, 0, 0.2]},
              {"type": "mesh", "file": "meshes/funnel.obj", "center": [0.5, 0.8, 0], "scale": 0.5,
               "open": true}],
    "objects": [{"name": "vessel", "motion": "deformable",
                 "shape": {"type": "tube", "center": [0.5, 0.3, 0], "radius": 0.05, "length": 0.4},
                 "deformable": {"stiffness": 30, "damping": 0.002, "breaking_strain": 0.3,
                                "spring_reach": 2.2,
                                "pinned": [{"min": [0.2, 0.2, -0.1], "max": [0.31, 0.4, 0.1]}],
                                "cuts": [{"min": [0.5, 0.2, -0.01], "max": [0.6, 0.26, 0.01]}],
                                "model": "xpbd", "substeps": 12, "bending_stiffness": 5}}],
    "interaction": {"coupling": "boundary", "influence_ratio": 1.8, "distance_exponent": 3,
                    "stiffness": 12, "damping": 0.5, "shear": 0.1, "max_acceleration": 900,
                    "cut_aware_damping": false},
    "object_engine": {"type": "bullet", "rate": 2, "own_thread": false},
    "calibration": {"mass": 0.008, "max_expected_speed": 3.5, "speed_of_sound": 35,
                    "stiffness": 1.75e5},
    "time": {"duration": 2.5, "cfl": 0.3, "force_factor": 0.2, "viscous_factor": 0.1,
             "max_dt": 0.005, "fixed_dt": 0.0001},
    "output": {"fps": 60, "format": "ply", "probe_rate": 250},
    "probes": [{"name": "sensor", "type": "point", "position": [1.4, 0.05, 0]},
               {"name": "gauge", "type": "level", "from": [0.5, 0, 0], "to": [0.5, 1, 0]},
               {"name": "on_vessel", "type": "force", "object": "vessel"},
               {"name": "on_crate", "type": "force", "wall": "crate"}],
    "emitters": [{"name": "tap", "shape": "disc", "center": [0.2, 0.9, 0], "radius": 0.05,
                  "direction": [0, -1, 0], "speed": 0.4, "start": 0.1, "end": 1.5},
                 {"name": "inlet", "shape": "rectangle", "corner": [0, 0.1, -0.1],
                  "edge1": [0, 0.2, 0], "edge2": [0, 0, 0.2], "speed": 0.25}],
    "outlets": [{"name": "drain", "min": [1.2, 0, -0.15], "max": [1.4, 0.1, 0.25]}],
    "failure": {"max_density_error": 0.2},
    "limits": {"max_particles": 2e6, "max_memory_gb": 4}
  })");
}

// The message parseScene throws for `document`, or a failure if it throws none.
inline std::string parseError(const nlohmann::json& document,
                              const std::vector<std::string>& overrides = {}) {
  try {
    parseScene(document, kSource, overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "parseScene accepted " << document.dump();
  return "";
}

inline void expectBoxesEqual(const AxisBox& a, const AxisBox& b) {
  EXPECT_EQ(a.min, b.min);
  EXPECT_EQ(a.max, b.max);
}

inline void expectScenesEqual(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  expectBoxesEqual(a.domain.box, b.domain.box);
  EXPECT_EQ(a.domain.outside, b.domain.outside);
  EXPECT_EQ(a.domain.dampedBox, b.domain.dampedBox);
  EXPECT_EQ(a.domain.damping, b.domain.damping);
  EXPECT_EQ(a.domain.periodic, b.domain.periodic);
  EXPECT_EQ(a.gravity, b.gravity);
  const FluidDesc& fa = a.fluid;
  const FluidDesc& fb = b.fluid;
  EXPECT_EQ(fa.restDensity, fb.restDensity);
  EXPECT_EQ(fa.spacing, fb.spacing);
  EXPECT_EQ(fa.supportRatio, fb.supportRatio);
  EXPECT_EQ(fa.solver, fb.solver);
  EXPECT_EQ(fa.dfsph.densityTolerance, fb.dfsph.densityTolerance);
  EXPECT_EQ(fa.dfsph.divergenceTolerance, fb.dfsph.divergenceTolerance);
  EXPECT_EQ(fa.dfsph.minIterations, fb.dfsph.minIterations);
  EXPECT_EQ(fa.dfsph.maxIterations, fb.dfsph.maxIterations);
  EXPECT_EQ(fa.dfsph.warmStart, fb.dfsph.warmStart);
  EXPECT_EQ(fa.dfsph.divergenceSolve, fb.dfsph.divergenceSolve);
  EXPECT_EQ(fa.dfsph.densitySolve, fb.dfsph.densitySolve);
  EXPECT_EQ(fa.dfsph.forceFactor, fb.dfsph.forceFactor);
  EXPECT_EQ(fa.kernel, fb.kernel);
  EXPECT_EQ(fa.eos, fb.eos);
  EXPECT_EQ(fa.clampNegativePressure, fb.clampNegativePressure);
  EXPECT_EQ(fa.pressureForm, fb.pressureForm);
  EXPECT_EQ(fa.viscosityModel, fb.viscosityModel);
  EXPECT_EQ(fa.viscosity, fb.viscosity);
  EXPECT_EQ(fa.wallFriction, fb.wallFriction);
  EXPECT_EQ(fa.surfaceTension, fb.surfaceTension);
  EXPECT_EQ(fa.surfaceThreshold, fb.surfaceThreshold);
  ASSERT_EQ(fa.blocks.size(), fb.blocks.size());
  for (std::size_t i = 0; i < fa.blocks.size(); ++i) {
    expectBoxesEqual(fa.blocks[i].box, fb.blocks[i].box);
    EXPECT_EQ(fa.blocks[i].velocity, fb.blocks[i].velocity);
    EXPECT_EQ(fa.blocks[i].angularVelocity, fb.blocks[i].angularVelocity);
  }
  ASSERT_EQ(a.walls.size(), b.walls.size());
  for (std::size_t i = 0; i < a.walls.size(); ++i) {
    const WallDesc& wa = a.walls[i];
    const WallDesc& wb = b.walls[i];
    EXPECT_EQ(wa.name, wb.name);
    EXPECT_EQ(wa.kind, wb.kind);
    expectBoxesEqual(wa.box, wb.box);
    EXPECT_EQ(wa.layers, wb.layers);
    EXPECT_EQ(wa.closed, wb.closed);
    EXPECT_EQ(wa.fluid, wb.fluid);
    EXPECT_EQ(wa.center, wb.center);
    EXPECT_EQ(wa.radius, wb.radius);
    EXPECT_EQ(wa.length, wb.length);
    EXPECT_EQ(wa.axis, wb.axis);
    EXPECT_EQ(wa.capped, wb.capped);
    EXPECT_EQ(wa.corner, wb.corner);
    EXPECT_EQ(wa.edge1, wb.edge1);
    EXPECT_EQ(wa.edge2, wb.edge2);
    EXPECT_EQ(wa.meshFile, wb.meshFile);
    EXPECT_EQ(wa.scale, wb.scale);
    EXPECT_EQ(wa.open, wb.open);
  }
  ASSERT_EQ(a.objects.size(), b.objects.size());
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    const DeformableDesc& da = a.objects[i].deformable;
    const DeformableDesc& db = b.objects[i].deformable;
    EXPECT_EQ(da.stiffness, db.stiffness);
    EXPECT_EQ(da.damping, db.damping);
    EXPECT_EQ(da.breakingStrain, db.breakingStrain);
    EXPECT_EQ(da.springReach, db.springReach);
    ASSERT_EQ(da.pinned.size(), db.pinned.size());
    for (std::size_t k = 0; k < da.pinned.size(); ++k) expectBoxesEqual(da.pinned[k], db.pinned[k]);
    ASSERT_EQ(da.cuts.size(), db.cuts.size());
    for (std::size_t k = 0; k < da.cuts.size(); ++k) expectBoxesEqual(da.cuts[k], db.cuts[k]);
    EXPECT_EQ(da.model, db.model);
    EXPECT_EQ(da.substeps, db.substeps);
    EXPECT_EQ(da.bendingStiffness, db.bendingStiffness);
  }
  EXPECT_EQ(a.interaction.coupling, b.interaction.coupling);
  EXPECT_EQ(a.interaction.influenceRatio, b.interaction.influenceRatio);
  EXPECT_EQ(a.interaction.distanceExponent, b.interaction.distanceExponent);
  EXPECT_EQ(a.interaction.stiffness, b.interaction.stiffness);
  EXPECT_EQ(a.interaction.damping, b.interaction.damping);
  EXPECT_EQ(a.interaction.shear, b.interaction.shear);
  EXPECT_EQ(a.interaction.maxAcceleration, b.interaction.maxAcceleration);
  EXPECT_EQ(a.interaction.cutAwareDamping, b.interaction.cutAwareDamping);
  EXPECT_EQ(a.objectEngine.type, b.objectEngine.type);
  EXPECT_EQ(a.objectEngine.rate, b.objectEngine.rate);
  EXPECT_EQ(a.objectEngine.ownThread, b.objectEngine.ownThread);
  EXPECT_EQ(a.calibration.mass, b.calibration.mass);
  EXPECT_EQ(a.calibration.maxExpectedSpeed, b.calibration.maxExpectedSpeed);
  EXPECT_EQ(a.calibration.speedOfSound, b.calibration.speedOfSound);
  EXPECT_EQ(a.calibration.stiffness, b.calibration.stiffness);
  EXPECT_EQ(a.time.duration, b.time.duration);
  EXPECT_EQ(a.time.cfl, b.time.cfl);
  EXPECT_EQ(a.time.forceFactor, b.time.forceFactor);
  EXPECT_EQ(a.time.viscousFactor, b.time.viscousFactor);
  EXPECT_EQ(a.time.maxDt, b.time.maxDt);
  EXPECT_EQ(a.time.fixedDt, b.time.fixedDt);
  EXPECT_EQ(a.output.fps, b.output.fps);
  EXPECT_EQ(a.output.format, b.output.format);
  EXPECT_EQ(a.output.probeRate, b.output.probeRate);
  ASSERT_EQ(a.probes.size(), b.probes.size());
  for (std::size_t i = 0; i < a.probes.size(); ++i) {
    EXPECT_EQ(a.probes[i].name, b.probes[i].name);
    EXPECT_EQ(a.probes[i].kind, b.probes[i].kind);
    EXPECT_EQ(a.probes[i].position, b.probes[i].position);
    EXPECT_EQ(a.probes[i].from, b.probes[i].from);
    EXPECT_EQ(a.probes[i].to, b.probes[i].to);
    EXPECT_EQ(a.probes[i].object, b.probes[i].object);
    EXPECT_EQ(a.probes[i].wall, b.probes[i].wall);
  }
  ASSERT_EQ(a.emitters.size(), b.emitters.size());
  for (std::size_t i = 0; i < a.emitters.size(); ++i) {
    const EmitterDesc& x = a.emitters[i];
    const EmitterDesc& y = b.emitters[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.shape, y.shape);
    EXPECT_EQ(x.speed, y.speed);
    EXPECT_EQ(x.start, y.start);
    EXPECT_EQ(x.end, y.end);
    if (x.shape == EmitterShape::Disc) {
      EXPECT_EQ(x.center, y.center);
      EXPECT_EQ(x.radius, y.radius);
      EXPECT_EQ(x.direction, y.direction);
    } else {
      EXPECT_EQ(x.corner, y.corner);
      EXPECT_EQ(x.edge1, y.edge1);
      EXPECT_EQ(x.edge2, y.edge2);
    }
  }
  ASSERT_EQ(a.outlets.size(), b.outlets.size());
  for (std::size_t i = 0; i < a.outlets.size(); ++i) {
    EXPECT_EQ(a.outlets[i].name, b.outlets[i].name);
    expectBoxesEqual(a.outlets[i].box, b.outlets[i].box);
  }
  EXPECT_EQ(a.failure.maxDensityError, b.failure.maxDensityError);
}

}  // namespace sph::io::scene_test
