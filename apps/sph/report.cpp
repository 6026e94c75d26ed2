#include "report.hpp"

#include <string>

#include "sph/error.hpp"
#include "sph/io/frame_writer.hpp"
#include "sph/threads.hpp"

namespace sph::cli {

namespace {

const char* origin(bool fromScene) {
  return fromScene ? "set by scene" : "derived";
}

const char* eosStiffnessName(EquationOfState eos) {
  switch (eos) {
    case EquationOfState::Linear:
      return "k (p = k(rho - rho0))";
    case EquationOfState::Ratio:
      return "k (p = k(rho/rho0 - 1))";
    default:
      return "B (Tait)";
  }
}

}  // namespace

void printCalibration(std::FILE* out, const Simulation& sim) {
  const Calibration& c = sim.calibration();
  const Scene& s = sim.scene();
  std::fprintf(out, "scene %s: %llu fluid particles, %llu boundary particles\n",
               s.sourcePath.c_str(), static_cast<unsigned long long>(c.fluidParticles),
               static_cast<unsigned long long>(c.boundaryParticles));
  std::fprintf(out, "  spacing d            %.6g m, support radius h = %.6g m\n", c.spacing,
               c.supportRadius);
  std::fprintf(out, "  particle mass        %.6g kg (%s)\n", c.mass, origin(c.massFromScene));
  std::fprintf(out, "  max expected speed   %.6g m/s (%s)\n", c.maxExpectedSpeed,
               origin(c.maxExpectedSpeedFromScene));
  std::fprintf(out, "  speed of sound c0    %.6g m/s (%s)\n", c.soundSpeed,
               origin(c.soundSpeedFromScene));
  std::fprintf(out, "  stiffness %-10s %.6g (%s)\n", eosStiffnessName(s.fluid.eos), c.stiffness,
               origin(c.stiffnessFromScene));
  std::fprintf(out, "  kinematic viscosity  %.6g m^2/s\n", c.kinematicViscosity);
  std::fprintf(out, "  surface threshold    |grad c| > %.6g 1/m (%s)\n", c.surfaceThreshold,
               origin(s.fluid.surfaceThreshold.has_value()));
  if (s.fluid.solver == FluidSolver::Dfsph) {
    const DfsphDesc& d = s.fluid.dfsph;
    std::fprintf(out,
                 "  solver               incompressible (dfsph): density tolerance %.3g %%, "
                 "divergence %.3g %%, %d-%d iterations, warm start %s\n",
                 100.0 * d.densityTolerance, 100.0 * d.divergenceTolerance, d.minIterations,
                 d.maxIterations, d.warmStart ? "on" : "off");
    std::fprintf(out, "  density solve        coarse level %.3g of its K\n", d.coarseCorrection);
    std::fprintf(out,
                 "  first time step      %.6g s (adaptive unless time.fixed_dt: CFL %.3g h/v_max, "
                 "force factor %.3g; c0 sets the artificial viscosity only)\n",
                 c.initialDt, s.time.cfl, d.forceFactor);
  } else if (s.fluid.solver == FluidSolver::Pbf) {
    const PbfDesc& d = s.fluid.pbf;
    std::fprintf(out,
                 "  solver               position based (pbf): %d iterations a substep, relaxation "
                 "eps %.6g 1/m^2 (%.3g of a full lattice's)\n",
                 d.iterations, d.relaxation * c.pbfGradientSquares, d.relaxation);
    std::fprintf(out, "  substeps             %d a frame step of %.6g s: %.6g s each (%s%s)\n",
                 c.substeps, s.time.frameDt, c.initialDt,
                 s.time.fixedDt ? "time.fixed_dt" : origin(c.substepsFromScene),
                 c.substepsFromScene || s.time.fixedDt
                     ? ""
                     : ": no particle moves 0.4 of its radius in one at the expected speed");
    std::fprintf(out,
                 "  tensile correction   k %.3g of a full lattice's lambda scale at dq %.3g h; "
                 "XSPH c %.3g; pressure from the "
                 "multipliers, -rho0 sum(lambda) / dt^2\n",
                 d.tensileStrength, d.tensileDistance, d.xsph);
    std::fprintf(out,
                 "  speed guard          %.6g m/s: no predicted move past half the support "
                 "radius in a substep (each limited speed counted in clamped_count)\n",
                 c.pbfSpeedGuard);
  } else {
    std::fprintf(out, "  solver               weakly compressible (wcsph)\n");
    std::fprintf(out, "  first time step      %.6g s (CFL %.3g; adaptive unless time.fixed_dt)\n",
                 c.initialDt, s.time.cfl);
  }
  if (!s.probes.empty()) {
    std::string names;
    for (const ProbeDesc& p : s.probes) {
      const char* kind = p.kind == ProbeKind::Point   ? "point"
                         : p.kind == ProbeKind::Level ? "level"
                                                      : "force";
      names += (names.empty() ? "" : ", ") + p.name + " (" + kind + ")";
    }
    std::fprintf(out, "  probes               %zu at %g per second: %s\n", s.probes.size(),
                 s.output.probeRate, names.c_str());
  }
  const std::vector<FlowStats> emitters = sim.emitterStats();
  for (std::size_t k = 0; k < emitters.size(); ++k) {
    const EmitterDesc& e = s.emitters[k];
    std::fprintf(out,
                 "  emitter %-12s %.0f particles a layer at %.6g m/s: %.6g particles/s, %.6g kg/s, "
                 "from %g s to %g s\n",
                 e.name.c_str(), emitters[k].rate * c.spacing / e.speed, e.speed, emitters[k].rate,
                 emitters[k].rate * c.mass, e.start, e.end);
  }
  for (const OutletDesc& o : s.outlets)
    std::fprintf(out, "  outlet %-13s removes what enters [%g, %g, %g] to [%g, %g, %g]\n",
                 o.name.c_str(), o.box.min[0], o.box.min[1], o.box.min[2], o.box.max[0],
                 o.box.max[1], o.box.max[2]);
  if (s.objects.empty()) return;
  std::fprintf(out, "  objects              %zu, %llu particles\n", s.objects.size(),
               static_cast<unsigned long long>(c.objectParticles));
  std::fprintf(out, "  coupling             %s\n",
               c.objectsAsBoundary ? "boundary particles of the pressure solve (Akinci et al. 2012)"
                                   : "contact forces (Meteer 2011, eqs. 13-16)");
  std::fprintf(out, "  contact k_spring     %.6g N/m (%s)\n", c.contactStiffness,
               origin(c.contactStiffnessFromScene));
  std::fprintf(out, "  contact k_damping    %.6g N s/m (%s)\n", c.contactDamping,
               origin(c.contactDampingFromScene));
  std::fprintf(out, "  contact k_shear      %.6g N s/m (%s)\n", c.contactShear,
               origin(c.contactShearFromScene));
  std::fprintf(out, "  max acceleration     %.6g m/s^2 (%s)\n", c.maxAcceleration,
               origin(c.maxAccelerationFromScene));
  std::fprintf(out, "  influence sphere     %.3g x the object particle radius\n",
               s.interaction.influenceRatio);
}

nlohmann::json calibrationJson(const Calibration& c) {
  return {{"spacing", c.spacing},
          {"support_radius", c.supportRadius},
          {"mass", c.mass},
          {"mass_from_scene", c.massFromScene},
          {"max_expected_speed", c.maxExpectedSpeed},
          {"max_expected_speed_from_scene", c.maxExpectedSpeedFromScene},
          {"speed_of_sound", c.soundSpeed},
          {"speed_of_sound_from_scene", c.soundSpeedFromScene},
          {"stiffness", c.stiffness},
          {"stiffness_from_scene", c.stiffnessFromScene},
          {"kinematic_viscosity", c.kinematicViscosity},
          {"initial_dt", c.initialDt},
          {"surface_threshold", c.surfaceThreshold},
          {"contact_stiffness", c.contactStiffness},
          {"contact_damping", c.contactDamping},
          {"contact_shear", c.contactShear},
          {"max_acceleration", c.maxAcceleration},
          {"objects_as_boundary", c.objectsAsBoundary},
          {"fluid_particles", c.fluidParticles},
          {"object_particles", c.objectParticles},
          {"boundary_particles", c.boundaryParticles}};
}

nlohmann::json statsJson(const FrameStats& s) {
  return {{"time", s.time},
          {"steps", s.steps},
          {"dt", s.dt},
          {"fluid_count", s.fluidCount},
          {"boundary_count", s.boundaryCount},
          {"kinetic_energy", s.kineticEnergy},
          {"mean_density", s.meanDensity},
          {"average_density_error", s.averageDensityError},
          {"max_density_error", s.maxDensityError},
          {"max_speed", s.maxSpeed},
          {"surface_count", s.surfaceCount},
          {"leaked_count", s.leakedCount},
          {"removed_count", s.removedCount},
          {"emitted_count", s.emittedCount},
          {"clamped_count", s.clampedCount},
          {"contact_pairs", s.contactPairs},
          {"density_iterations_per_step",
           s.steps ? double(s.densityIterations) / double(s.steps) : 0.0},
          {"divergence_iterations_per_step",
           s.steps ? double(s.divergenceIterations) / double(s.steps) : 0.0},
          {"unconverged_solves", s.unconvergedSolves},
          {"objects", objectsJson(s.objects)},
          {"wall_ms_per_step", s.wallMsPerStep}};
}

nlohmann::json flowJson(const std::vector<FlowStats>& flows) {
  nlohmann::json out = nlohmann::json::array();
  for (const FlowStats& f : flows)
    out.push_back({{"name", f.name}, {"particles", f.particles}, {"mass_kg", f.mass}});
  return out;
}

nlohmann::json objectsJson(const std::vector<ObjectStats>& objects) {
  nlohmann::json out = nlohmann::json::array();
  for (const ObjectStats& o : objects) {
    nlohmann::json object = {{"name", o.name},
                             {"centre_of_mass", o.centreOfMass},
                             {"velocity", o.velocity},
                             {"fluid_force", o.fluidForce},
                             {"contact_force", o.contactForce},
                             {"broken_springs", o.brokenSprings}};
    if (o.volumeRatio > 0.0) object["volume_ratio"] = o.volumeRatio;
    out.push_back(object);
  }
  return out;
}

const char* backendName() {
  return "cpu";
}

const char* formatName(FrameFormat format) {
  const char* extension = io::frameExtension(format);
  return *extension ? extension : "none";
}

}  // namespace sph::cli
