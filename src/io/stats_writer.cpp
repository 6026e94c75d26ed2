#include "sph/io/stats_writer.hpp"

#include <cinttypes>
#include <string>
#include <utility>

namespace sph::io {

namespace {

std::string headerOf(const std::vector<std::string>& objectNames) {
  std::string header =
      "time,steps,dt,fluid_count,boundary_count,kinetic_energy,mean_density,"
      "max_density_error,max_speed,surface_count,leaked_count,removed_count,"
      "wall_ms_per_step,contact_pairs,average_density_error,density_iterations_per_step,"
      "divergence_iterations_per_step,unconverged_solves,emitted_count,clamped_count";
  for (const std::string& name : objectNames) {
    for (const char* column : {"_force_x", "_force_y", "_force_z", "_com_x", "_com_y", "_com_z"})
      header += "," + name + column;
  }
  return header + "\n";
}

}  // namespace

StatsWriter::StatsWriter(std::filesystem::path csvFile, std::vector<std::string> objectNames)
    : objectCount_(objectNames.size()), file_(std::move(csvFile), headerOf(objectNames)) {}

StatsWriter::StatsWriter(std::filesystem::path csvFile, std::vector<std::string> objectNames,
                         RowFile::Continue from, const FrameStats& previous)
    : objectCount_(objectNames.size()), previous_(previous), file_(std::move(csvFile), from) {}

void StatsWriter::append(const FrameStats& s) {
  const std::uint64_t steps = s.steps - previous_.steps;
  const auto perStep = [&](std::uint64_t count) {
    return steps ? double(count) / double(steps) : 0.0;
  };
  std::string row;
  appendFormatted(row,
                  "%.9g,%" PRIu64 ",%.9g,%" PRIu64 ",%" PRIu64 ",%.9g,%.9g,%.9g,%.9g,%" PRIu64
                  ",%" PRIu64 ",%" PRIu64 ",%.9g,%" PRIu64 ",%.9g,%.9g,%.9g,%" PRIu64 ",%" PRIu64
                  ",%" PRIu64,
                  s.time, s.steps, s.dt, s.fluidCount, s.boundaryCount, s.kineticEnergy,
                  s.meanDensity, s.maxDensityError, s.maxSpeed, s.surfaceCount, s.leakedCount,
                  s.removedCount, s.wallMsPerStep, s.contactPairs, s.averageDensityError,
                  perStep(s.densityIterations - previous_.densityIterations),
                  perStep(s.divergenceIterations - previous_.divergenceIterations),
                  s.unconvergedSolves, s.emittedCount, s.clampedCount);
  for (std::size_t o = 0; o < objectCount_; ++o) {
    // A row without the objects (a caller that does not track them) leaves their cells empty.
    const bool known = o < s.objects.size();
    const ObjectStats& object = known ? s.objects[o] : ObjectStats{};
    for (double v : {object.fluidForce[0], object.fluidForce[1], object.fluidForce[2],
                     object.centreOfMass[0], object.centreOfMass[1], object.centreOfMass[2]}) {
      if (known) {
        appendFormatted(row, ",%.9g", v);
      } else {
        row += ",";
      }
    }
  }
  row += "\n";
  file_.append(row);
  previous_ = s;
}

}  // namespace sph::io
