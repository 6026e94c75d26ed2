#include "io/stats_writer.hpp"

#include <cerrno>
#include <cinttypes>
#include <string>
#include <utility>

#include "io/file_error.hpp"

namespace sph::io {

StatsWriter::StatsWriter(std::filesystem::path csvFile, std::vector<std::string> objectNames)
    : path_(std::move(csvFile)), objectCount_(objectNames.size()) {
  errno = 0;
  file_.reset(std::fopen(path_.string().c_str(), "w"));
  if (!file_) throwFileError("open", path_, errno);
  std::string header =
      "time,steps,dt,fluid_count,boundary_count,kinetic_energy,mean_density,"
      "max_density_error,max_speed,surface_count,leaked_count,removed_count,"
      "wall_ms_per_step,contact_pairs,average_density_error,density_iterations_per_step,"
      "divergence_iterations_per_step,unconverged_solves,emitted_count";
  for (const std::string& name : objectNames) {
    for (const char* column : {"_force_x", "_force_y", "_force_z", "_com_x", "_com_y", "_com_z"})
      header += "," + name + column;
  }
  header += "\n";
  errno = 0;
  if (std::fputs(header.c_str(), file_.get()) < 0) throwFileError("write", path_, errno);
  flushOrThrow();
}

void StatsWriter::append(const FrameStats& s) {
  const std::uint64_t steps = s.steps - previous_.steps;
  const auto perStep = [&](std::uint64_t count) {
    return steps ? double(count) / double(steps) : 0.0;
  };
  errno = 0;
  const int written =
      std::fprintf(file_.get(),
                   "%.9g,%" PRIu64 ",%.9g,%" PRIu64 ",%" PRIu64 ",%.9g,%.9g,%.9g,%.9g,%" PRIu64
                   ",%" PRIu64 ",%" PRIu64 ",%.9g,%" PRIu64 ",%.9g,%.9g,%.9g,%" PRIu64 ",%" PRIu64,
                   s.time, s.steps, s.dt, s.fluidCount, s.boundaryCount, s.kineticEnergy,
                   s.meanDensity, s.maxDensityError, s.maxSpeed, s.surfaceCount, s.leakedCount,
                   s.removedCount, s.wallMsPerStep, s.contactPairs, s.averageDensityError,
                   perStep(s.densityIterations - previous_.densityIterations),
                   perStep(s.divergenceIterations - previous_.divergenceIterations),
                   s.unconvergedSolves, s.emittedCount);
  if (written < 0) throwFileError("write", path_, errno);
  for (std::size_t o = 0; o < objectCount_; ++o) {
    // A row without the objects (a caller that does not track them) leaves their cells empty.
    const bool known = o < s.objects.size();
    const ObjectStats& object = known ? s.objects[o] : ObjectStats{};
    for (double v : {object.fluidForce[0], object.fluidForce[1], object.fluidForce[2],
                     object.centreOfMass[0], object.centreOfMass[1], object.centreOfMass[2]}) {
      if ((known ? std::fprintf(file_.get(), ",%.9g", v) : std::fputs(",", file_.get())) < 0)
        throwFileError("write", path_, errno);
    }
  }
  if (std::fputs("\n", file_.get()) < 0) throwFileError("write", path_, errno);
  flushOrThrow();
  previous_ = s;
}

// fflush hands the row to the kernel: that survives the process dying, which is what the
// contract asks; surviving a power cut would need fsync per row, too slow for no real need.
void StatsWriter::flushOrThrow() {
  errno = 0;
  if (std::fflush(file_.get()) != 0) throwFileError("write", path_, errno);
}

}  // namespace sph::io
