#include "scene/scene_loader.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <system_error>
#include <utility>

#include <nlohmann/json.hpp>

#include "scene/json_input.hpp"
#include "scene/scene_checks.hpp"
#include "scene/scene_flow.hpp"
#include "scene/scene_keys.hpp"
#include "scene/scene_overrides.hpp"
#include "scene/scene_reader.hpp"
#include "scene/scene_schema.hpp"
#include "sph/error.hpp"

namespace sph::scene {
namespace {

using nlohmann::json;

std::string solverName(FluidSolver solver) {
  for (const auto& named : kSolverNames)
    if (named.value == solver) return named.name;
  return "?";
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
    if (scene.objectEngine.type == ObjectEngineKind::Bullet)
      context.fail(joinIndex("fluid.blocks", b) + ".inside",
                   "not with object_engine.type \"bullet\" (Bullet's bodies are made outside the "
                   "simulation); expected no \"inside\"",
                   {"object_engine.type"});
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
                 "expected \"summation\" with fluid.solver \"" + solverName(scene.fluid.solver) +
                     "\" (\"continuity\" needs fluid.solver \"wcsph\"), got \"continuity\"",
                 {"fluid.solver"});
  if (scene.fluid.pressureForm != PressureForm::Symmetric)
    context.fail("fluid.density",
                 "expected \"summation\" with fluid.pressure_form \"paper\" (\"continuity\" "
                 "needs \"symmetric\"), got \"continuity\"",
                 {"fluid.pressure_form"});
}

// A periodic axis must hold the kernel's support three times (the grid's cells then see each
// neighbour once, through one image) and a whole number of spacings (the lattice then meets
// itself across the face). The built-in engine carries objects across a periodic face;
// Bullet's are not.
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
  if ((d.periodic[0] || d.periodic[1] || d.periodic[2]) && !scene.objects.empty() &&
      scene.objectEngine.type == ObjectEngineKind::Bullet)
    context.fail("domain.periodic",
                 "expected no periodic axes with object_engine.type \"bullet\" (Bullet's bodies "
                 "are not carried across a periodic face; the built-in engine's are), got \"" +
                     std::string(d.periodic[0] ? "x" : "") + (d.periodic[1] ? "y" : "") +
                     (d.periodic[2] ? "z" : "") + "\"",
                 {"object_engine.type"});
}

// Boundary coupling gives the objects the pressure of an incompressible solver, the
// velocity solver's or the position solver's: the weakly compressible one has none.
void checkCoupling(const ReadContext& context, const Scene& scene) {
  if (scene.interaction.coupling == ObjectCoupling::Boundary &&
      scene.fluid.solver == FluidSolver::Wcsph)
    context.fail("interaction.coupling",
                 "expected \"contact\" with fluid.solver \"wcsph\" (\"boundary\" needs "
                 "fluid.solver \"dfsph\" or \"pbf\"), got \"boundary\"");
}

// The position solver couples objects only as boundary particles of its density constraints
// (the contact springs would bound its substep by their stiffness), and gives no forces on
// walls.
void checkPositionSolver(const ReadContext& context, const Scene& scene) {
  if (scene.fluid.solver != FluidSolver::Pbf) return;
  if (!scene.objects.empty() && scene.interaction.coupling != ObjectCoupling::Boundary)
    context.fail("interaction.coupling",
                 "expected \"boundary\" with objects and fluid.solver \"pbf\" (the position "
                 "solver's density constraints push the objects' particles as they push the "
                 "walls'; contact springs would bound its substeps), got \"contact\"",
                 {"fluid.solver", "objects"});
  for (std::size_t k = 0; k < scene.probes.size(); ++k)
    if (scene.probes[k].kind == ProbeKind::Force && !scene.probes[k].wall.empty())
      context.fail("probes[" + std::to_string(k) + "].wall",
                   "expected no force probe on a wall with fluid.solver \"pbf\" (its "
                   "constraints give no forces on walls; \"wcsph\" and \"dfsph\" do), got \"" +
                       scene.probes[k].wall + "\"",
                   {"fluid.solver"});
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

// The checks that read more than one key, in the order a reader meets the keys.
void checkAcrossKeys(const ReadContext& context, const Scene& scene) {
  checkGeometry(context, scene);
  checkObjectNames(context, scene);
  checkWallNames(context, scene);
  checkCoupling(context, scene);
  checkPositionSolver(context, scene);
  checkPeriodic(context, scene);
  checkDensityModel(context, scene);
  checkProbes(context, scene);
  checkFlow(context, scene);
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
  readKeys(root, sceneKeys(), scene);
  checkAcrossKeys(context, scene);
  return scene;
}

// Written by the declarations and read back through them, the scene meets every key's limits
// and the checks across keys exactly as a file would: there is one set of rules, not a second
// copy for scenes built in code.
Scene validateScene(const Scene& scene) {
  Scene named = scene;
  nameUnnamedElements(named);
  parseScene(sceneToJson(named), scene.sourcePath.empty() ? "scene" : scene.sourcePath);
  return named;
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

}  // namespace sph::scene
