// The sph subcommands (the command-line contract in README.md). Each returns the process exit code:
// 0 done, 2 bad input, 3 the simulation failed.
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "sph/simulation.hpp"

namespace sph::cli {

enum ExitCode {
  kExitOk = 0,
  kExitBadInput = 2,
  kExitSimulationFailed = 3,
  kExitOutputFailed = 4  // a full disk, a read-only or vanished output directory
};

struct RunOptions {
  std::string scene;
  std::string out;              // default: out/<scene name>
  std::string backend = "cpu";  // until the GPU engine has run on a GPU (docs/gpu.md)
  int threads = 0;              // 0: all hardware threads
  int device = 0;               // CUDA device
  std::vector<std::string> overrides;
  bool force = false;
  bool quiet = false;
  bool render = false;           // then `sph render` the run's directory with its defaults
  bool surface = false;          // then `sph surface` it, with its defaults
  double checkpointEvery = 0.0;  // simulated seconds between checkpoints; 0: none
  std::string resume;            // a run's directory to continue from its newest checkpoint
  // Under mpirun (sph/process_group.hpp): Zoltan's method, and the load's drift that
  // partitions again.
  std::string partition = "rcb";
  double rebalanceAt = 1.05;
};

struct RenderOptions {
  std::string dir;
  std::string colour = "kind";  // kind, density, pressure, speed or surface
  // liquid or particles; empty: the scene's render.look, particles when colouring by a quantity
  std::string look;
  // surfaces: objects drawn as their surfaces (DIR/object_surfaces.vtp) where the run has them;
  // particles: as spheres
  std::string objects = "surfaces";
  std::vector<double> range;  // {min, max}; empty: from the run's fluid
  int width = 1280;
  int height = 720;
  double fps = 0.0;  // 0: the run's frame rate (summary.json), else 30
  bool noVideo = false;
  bool boundary = false;  // show the walls
  bool cutaway = false;   // leave out the walls and objects in front of the camera's target
  bool grid = false;      // show the domain and the uniform grid's cells
  double yaw = 35.0;      // the camera's angle about +y, degrees (0: looking along -z)
  double pitch = 25.0;    // and above the horizontal (negative: from below)
  bool quiet = false;
};

struct SurfaceOptions {
  std::string dir;
  std::string format = "vtp";  // vtp, obj or ply
  // The level set's voxel in spacings and its mean-curvature passes; none: the surface
  // library's defaults (surface::SurfaceSettings).
  std::optional<double> voxel;
  std::optional<int> smoothing;
  bool quiet = false;
};

struct ViewCommandOptions {
  std::string scene;
  std::string backend = "cpu";
  int threads = 0;
  int device = 0;
  std::vector<std::string> overrides;
  int width = 1280;
  int height = 720;
  std::string colour = "kind";
  std::string look;                  // liquid or particles; empty: the scene's
  std::string objects = "surfaces";  // or particles
  bool noProbe = false;
  int frames = 0;  // close after this many displayed frames (0: when the window closes)
  std::string screenshot;
};

struct BenchOptions {
  std::vector<int> sizes{4096, 16384, 65536, 262144};
  std::string backend = "cpu";  // until the GPU engine has run on a GPU (docs/gpu.md)
  int threads = 0;
  int device = 0;
  int warmupSteps = 20;
  int steps = 50;
  std::vector<std::string> scenes;  // also time these scene files
  std::vector<std::string> overrides;
  std::string json;  // also write the results here
  // Meteer 2011, §9: each scene with objects is timed at each of these influence ratios.
  std::vector<double> influenceRatios;
  // Each size and scene is timed with each of these solvers ("wcsph", "dfsph"); none: the
  // scene's own.
  std::vector<std::string> solvers;
};

struct PlotOptions {
  std::string dir;  // a run's output directory
  bool quiet = false;
};

int runCommand(const RunOptions& options);
// DIR/plots/stats.png and, with probes, DIR/plots/probes.png, drawn by gnuplot.
int plotCommand(const PlotOptions& options);
int validateCommand(const std::string& scene, const std::vector<std::string>& overrides);
int infoCommand();
int benchCommand(const BenchOptions& options);
// Images (DIR/images/frame_NNNNN.png) and a video (DIR/video.mp4) of a finished run.
int renderCommand(const RenderOptions& options);
// sph surface: each frame's fluid as a closed triangle mesh (surface_command.cpp).
int surfaceCommand(const SurfaceOptions& options);
bool surfaceBuilt();
// The interactive viewer (apps/view). Exit 1 when no window can be opened.
int viewCommand(const ViewCommandOptions& options);
bool viewerBuilt();
// False in builds without the renderer (SPH_WITH_VIEWER=OFF, or its libraries missing).
bool rendererBuilt();

// The options that choose where a Simulation runs. "cuda" without a usable GPU makes the
// Simulation throw an InputError that says why; "auto" takes the GPU when there is one.
SimulationOptions simulationOptions(const std::string& backend, int device);

// One line per GPU: name, compute capability, memory (total and free), for `sph info` and
// the start of a GPU run.
void printGpus(std::FILE* out);

}  // namespace sph::cli
