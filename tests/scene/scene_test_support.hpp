// Scene documents and helpers shared by the scene loader tests.
#pragma once

#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/scene_loader.hpp"
#include "sph/error.hpp"
#include "sph/scene.hpp"

namespace sph::scene::scene_test {

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
    "failure": {"max_density_error": 0.2, "max_speed": 12},
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

// Two scenes are the same when every key of the scene file holds the same value in both (the
// writer writes every key its declaration reads: SceneJson.WritesEveryKeyOfTheSchema).
inline void expectScenesEqual(const Scene& a, const Scene& b) {
  const nlohmann::json written = sceneToJson(a), expected = sceneToJson(b);
  EXPECT_EQ(written, expected) << "differences: " << nlohmann::json::diff(expected, written).dump();
}

}  // namespace sph::scene::scene_test
