// sph surface: each frame's fluid of a finished run as a closed triangle mesh
// (DIR/surface/frame_NNNNN.{vtp,obj,ply}) and a ParaView series of them (DIR/surface.pvd),
// through OpenVDB (apps/surface). Frames are meshed in parallel.
#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "mesh_files.hpp"
#include "particle_surface.hpp"
#include "run_summary.hpp"
#include "sph/error.hpp"
#include "sph/io/frame_reader.hpp"
#include "sph/io/pvd_series.hpp"

namespace sph::cli {

namespace fs = std::filesystem;

namespace {

// The fluid's spacing, from the run's summary.json (its resolved scene).
double runSpacing(const fs::path& dir) {
  const fs::path file = dir / "summary.json";
  const std::optional<nlohmann::json> summary = readRunSummary(dir);
  if (!summary)
    throw InputError(file.string() +
                     ": not found: the fluid's spacing sizes the surface's level set");
  const std::optional<double> spacing = summaryNumber(*summary, "/scene/fluid/spacing", file);
  if (!spacing || !(*spacing > 0))
    throw InputError(file.string() + ": key 'scene/fluid/spacing': expected a positive number");
  return *spacing;
}

surface::MeshFormat formatOf(const std::string& name) {
  if (name == "obj") return surface::MeshFormat::Obj;
  if (name == "ply") return surface::MeshFormat::Ply;
  return surface::MeshFormat::Vtp;
}

std::vector<float> fluidPositions(const ParticleFrame& frame) {
  std::vector<float> points;
  for (std::size_t i = 0; i < frame.size(); ++i)
    if (frame.kind[i] == static_cast<std::uint8_t>(ParticleKind::Fluid))
      points.insert(points.end(), &frame.position[3 * i], &frame.position[3 * i] + 3);
  return points;
}

// Meshes left from an earlier run of another format or more frames would otherwise sit beside
// the new ones.
void clearSurfaces(const fs::path& folder) {
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) throw OutputError(folder.string() + ": cannot create: " + error.message());
  for (const fs::directory_entry& entry : fs::directory_iterator(folder))
    if (entry.path().filename().string().rfind("frame_", 0) == 0) fs::remove(entry.path());
}

}  // namespace

bool surfaceBuilt() {
  return true;
}

int surfaceCommand(const SurfaceOptions& options) {
  const fs::path dir = options.dir;
  const io::RunFrameFiles files = io::listRunFrames(dir);
  surface::SurfaceSettings settings;
  settings.spacing = runSpacing(dir);
  if (options.voxel) settings.voxel = *options.voxel;
  if (options.smoothing) settings.smoothing = *options.smoothing;
  const surface::MeshFormat format = formatOf(options.format);
  const fs::path folder = dir / "surface";
  clearSurfaces(folder);
  const std::size_t n = files.frames.size();
  if (!options.quiet)
    std::printf("meshing the fluid of %zu frames of %s: voxel %g m, %d smoothing passes\n", n,
                dir.c_str(), settings.voxel * settings.spacing, settings.smoothing);

  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> names(n);
  std::vector<std::exception_ptr> errors(n);
  std::atomic<std::size_t> done{0};
  std::mutex print;
  std::size_t reported = 0;
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t k = 0; k < n; ++k) {
    try {
      const surface::TriangleMesh mesh =
          surface::reconstructSurface(fluidPositions(io::readFrame(files.frames[k])), settings);
      char name[40];
      std::snprintf(name, sizeof name, "frame_%05zu.%s", k, surface::extensionOf(format));
      surface::writeMesh(folder / name, mesh, format);
      names[k] = std::string("surface/") + name;
    } catch (...) {
      errors[k] = std::current_exception();
    }
    const std::size_t finished = ++done;
    std::lock_guard<std::mutex> lock(print);
    if (!options.quiet && finished * 10 / n > reported) {
      reported = finished * 10 / n;
      std::printf("  %zu/%zu surfaces\n", finished, n);
      std::fflush(stdout);
    }
  }
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);

  io::PvdSeries series(dir / "surface.pvd");
  for (std::size_t k = 0; k < n; ++k)
    series.add(files.times.empty() ? double(k) : files.times[k], names[k]);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!options.quiet)
    std::printf(
        "surfaces: %s/frame_00000.%s ... (%zu, %.2f s each); open %s/surface.pvd in "
        "ParaView beside the particles\n",
        folder.c_str(), surface::extensionOf(format), n, seconds / double(n), dir.c_str());
  return kExitOk;
}

}  // namespace sph::cli
