// sph: run, check and measure SPH scenes from the command line.
#include <CLI/CLI.hpp>

#include <cstdio>

#include "commands.hpp"
#include "sph/error.hpp"

// More threads than any machine sph runs on has cores; 20,000 took OpenMP a minute to start.
constexpr int kMostThreads = 1024;

int main(int argc, char** argv) {
  using namespace sph::cli;
  CLI::App app{"sph: real-time SPH fluids on the CPU (OpenMP) and NVIDIA GPUs"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Help for every subcommand");

  RunOptions run;
  std::string duration, fps, format;
  auto* runCmd = app.add_subcommand("run", "Simulate a scene and write frames and statistics");
  runCmd->add_option("scene", run.scene, "Scene file (JSON); not with --resume");
  runCmd->add_option("--out", run.out, "Output directory (default: out/<scene name>)");
  runCmd->add_option("--backend", run.backend, "cpu, cuda or auto")
      ->check(CLI::IsMember({"cpu", "cuda", "auto"}));
  runCmd->add_option("--threads", run.threads, "CPU threads, at most 1024 (default: all)")
      ->check(CLI::Range(0, kMostThreads));
  runCmd
      ->add_option("--device", run.device,
                   "CUDA device index (see sph info); under mpirun, each process takes the one its "
                   "rank on its machine further on")
      ->check(CLI::NonNegativeNumber);
  runCmd->add_option("--duration", duration, "Simulated seconds (time.duration)");
  runCmd->add_option("--fps", fps, "Output frames per simulated second (output.fps)");
  runCmd->add_option("--format", format, "Frame format: vtp, ply, csv or none (output.format)")
      ->check(CLI::IsMember({"vtp", "ply", "csv", "none"}));
  runCmd->add_option("--set", run.overrides, "Override a scene key: dotted.key=value")->take_all();
  runCmd->add_flag("--force", run.force, "Overwrite an earlier run in the output directory");
  runCmd->add_flag("--quiet", run.quiet, "No progress output");
  runCmd
      ->add_option("--checkpoint-every", run.checkpointEvery,
                   "Save the whole state every T simulated seconds (at the first frame past), and "
                   "at the end, into DIR/checkpoints/ (the last two kept)")
      ->check(CLI::PositiveNumber);
  runCmd->add_option("--resume", run.resume,
                     "Continue the run in DIR from its newest checkpoint (a longer --duration "
                     "extends it)");
  runCmd
      ->add_option("--partition", run.partition,
                   "Under mpirun: Zoltan's partition of the particles among the processes, rcb "
                   "(boxes) or hsfc (a Hilbert curve) (default: rcb)")
      ->check(CLI::IsMember({"rcb", "hsfc"}));
  runCmd
      ->add_option("--rebalance-at", run.rebalanceAt,
                   "Under mpirun: partition again when the busiest process's work over the "
                   "mean have grown this many times since the last partition (default: 1.05)")
      ->check(CLI::Range(1.0, 100.0));
  runCmd->add_flag("--render", run.render,
                   "Then render the run: DIR/images/*.png and DIR/video.mp4 (as sph render)");
  runCmd->add_flag("--surface", run.surface,
                   "Then mesh the fluid of each frame: DIR/surface/*.vtp (as sph surface)");

  std::string validateScene;
  std::vector<std::string> validateOverrides;
  auto* validateCmd = app.add_subcommand("validate", "Check a scene and print derived values");
  validateCmd->add_option("scene", validateScene, "Scene file (JSON)")->required();
  validateCmd->add_option("--set", validateOverrides, "Override a scene key: dotted.key=value")
      ->take_all();

  auto* infoCmd = app.add_subcommand("info", "Build, backends and devices");

  PlotOptions plot;
  auto* plotCmd = app.add_subcommand(
      "plot", "Draw a run's stats.csv and probes.csv against time: DIR/plots/*.png (gnuplot)");
  plotCmd->add_option("dir", plot.dir, "The run's output directory (sph run --out DIR)")
      ->required();
  plotCmd->add_flag("--quiet", plot.quiet, "Print nothing but errors");

  RenderOptions render;
  auto* renderCmd =
      app.add_subcommand("render", "Images and a video of an earlier run, without a display");
  renderCmd->add_option("dir", render.dir, "The run's output directory (sph run --out DIR)")
      ->required();
  renderCmd->add_option("--colour,--color", render.colour, "Colour by what (default: kind)")
      ->check(CLI::IsMember({"kind", "density", "pressure", "speed", "surface"}));
  renderCmd
      ->add_option("--look", render.look,
                   "The fluid as a liquid surface or as particles (default: the scene's "
                   "render.look, liquid unless set; particles with a --colour other than kind)")
      ->check(CLI::IsMember({"liquid", "particles"}));
  renderCmd
      ->add_option("--objects", render.objects,
                   "Objects drawn as their surfaces, deforming and opening where they tear, or "
                   "as particles (default: surfaces)")
      ->check(CLI::IsMember({"surfaces", "particles"}));
  renderCmd
      ->add_option("--range", render.range,
                   "MIN,MAX of the colour map (default: the fluid's 2nd-98th percentile)")
      ->delimiter(',')
      ->expected(2);
  renderCmd->add_option("--width", render.width, "Image width in pixels")
      ->check(CLI::Range(16, 8192));
  renderCmd->add_option("--height", render.height, "Image height in pixels")
      ->check(CLI::Range(16, 8192));
  renderCmd->add_option("--fps", render.fps, "Video frames per second (default: the run's)")
      ->check(CLI::PositiveNumber);
  renderCmd->add_flag("--no-video", render.noVideo, "Images only");
  renderCmd->add_flag("--boundary", render.boundary, "Show the walls (DIR/boundary.EXT)");
  renderCmd->add_flag("--grid", render.grid, "Show the domain box and the uniform grid's cells");
  renderCmd->add_flag("--cutaway", render.cutaway,
                      "Leave out the objects and walls in front of the view's centre, to show "
                      "the fluid inside them");
  renderCmd
      ->add_option("--yaw", render.yaw,
                   "The camera's angle about the vertical, degrees (default: 35, from the front "
                   "right)")
      ->check(CLI::Range(-360.0, 360.0));
  renderCmd
      ->add_option("--pitch", render.pitch,
                   "The camera's angle above the horizontal, degrees; negative looks from below "
                   "(default: 25)")
      ->check(CLI::Range(-85.0, 85.0));
  renderCmd->add_flag("--quiet", render.quiet, "No progress output");

  SurfaceOptions surface;
  auto* surfaceCmd = app.add_subcommand(
      "surface", "Each frame's fluid of an earlier run as a closed triangle mesh (OpenVDB)");
  surfaceCmd->add_option("dir", surface.dir, "The run's output directory (sph run --out DIR)")
      ->required();
  surfaceCmd->add_option("--format", surface.format, "Mesh files: vtp, obj or ply (default: vtp)")
      ->check(CLI::IsMember({"vtp", "obj", "ply"}));
  surfaceCmd
      ->add_option("--voxel", surface.voxel,
                   "The level set's voxel edge in fluid spacings (default: 0.6)")
      ->check(CLI::Range(0.05, 4.0));
  surfaceCmd
      ->add_option("--smoothing", surface.smoothing,
                   "Mean-curvature smoothing passes of the level set (default: 3)")
      ->check(CLI::Range(0, 100));
  surfaceCmd->add_flag("--quiet", surface.quiet, "No progress output");

  ViewCommandOptions view;
  auto* viewCmd = app.add_subcommand("view", "The interactive viewer: a window that runs a scene");
  viewCmd->add_option("scene", view.scene, "Scene file (JSON)")->required();
  viewCmd->add_option("--backend", view.backend, "cpu, cuda or auto")
      ->check(CLI::IsMember({"cpu", "cuda", "auto"}));
  viewCmd->add_option("--threads", view.threads, "CPU threads, at most 1024 (default: all)")
      ->check(CLI::Range(0, kMostThreads));
  viewCmd->add_option("--device", view.device, "CUDA device index (see sph info)")
      ->check(CLI::NonNegativeNumber);
  viewCmd->add_option("--set", view.overrides, "Override a scene key: dotted.key=value")
      ->take_all();
  viewCmd->add_option("--width", view.width, "Window width in pixels")->check(CLI::Range(16, 8192));
  viewCmd->add_option("--height", view.height, "Window height in pixels")
      ->check(CLI::Range(16, 8192));
  viewCmd->add_option("--colour,--color", view.colour, "Colour by what (default: kind)")
      ->check(CLI::IsMember({"kind", "density", "pressure", "speed", "surface"}));
  viewCmd
      ->add_option("--look", view.look,
                   "The fluid as a liquid surface or as particles (default: the scene's "
                   "render.look, liquid unless set; particles with a --colour other than kind)")
      ->check(CLI::IsMember({"liquid", "particles"}));
  viewCmd
      ->add_option("--objects", view.objects,
                   "Objects drawn as their surfaces, deforming and opening where they tear, or "
                   "as particles (default: surfaces)")
      ->check(CLI::IsMember({"surfaces", "particles"}));
  viewCmd->add_flag("--no-probe", view.noProbe, "No sphere for the mouse to drag");
  viewCmd->add_option("--frames", view.frames, "Close after this many displayed frames")
      ->check(CLI::NonNegativeNumber);
  viewCmd->add_option("--screenshot", view.screenshot, "Write the last frame to this PNG file");

  BenchOptions bench;
  auto* benchCmd =
      app.add_subcommand("bench", "Milliseconds per step by stage (Meteer 2011's box drop)");
  benchCmd->add_option("--sizes", bench.sizes, "Particle counts")
      ->delimiter(',')
      ->check(CLI::Range(1, 1 << 30));
  benchCmd->add_option("--backend", bench.backend, "cpu, cuda or auto")
      ->check(CLI::IsMember({"cpu", "cuda", "auto"}));
  benchCmd->add_option("--threads", bench.threads, "CPU threads, at most 1024 (default: all)")
      ->check(CLI::Range(0, kMostThreads));
  benchCmd->add_option("--device", bench.device, "CUDA device index (see sph info)")
      ->check(CLI::NonNegativeNumber);
  benchCmd->add_option("--warmup", bench.warmupSteps, "Steps before timing");
  benchCmd->add_option("--steps", bench.steps, "Timed steps per size")->check(CLI::PositiveNumber);
  benchCmd->add_option("--scene", bench.scenes, "Also time this scene file (repeatable)");
  benchCmd->add_option("--set", bench.overrides, "Override a key of the --scene files")->take_all();
  benchCmd->add_option("--json", bench.json,
                       "Also write the results to this file, one JSON object per line");
  benchCmd
      ->add_option("--influence", bench.influenceRatios,
                   "Time each --scene with objects at these influence sphere radii (x the object "
                   "particle radius), e.g. 1,1.5,2,3 (Meteer 2011, §9)")
      ->delimiter(',')
      ->check(CLI::Range(1.0, 4.0));
  benchCmd
      ->add_option("--solver", bench.solvers,
                   "Time each size and scene with these solvers, side by side: wcsph, dfsph, "
                   "pbf (default: the scene's own; objects couple by contact under wcsph, as "
                   "boundary particles under pbf)")
      ->delimiter(',')
      ->check(CLI::IsMember({"wcsph", "dfsph", "pbf"}));

  auto dispatch = [&]() -> int {
    if (*runCmd) {
      if (!run.resume.empty()) {
        // A resumed run continues its own scene and outputs: only its end may move.
        if (!run.scene.empty() || !run.overrides.empty() || !fps.empty() || !format.empty() ||
            !run.out.empty() || run.force) {
          std::fprintf(stderr,
                       "error: --resume %s: continues the run's own scene into its own directory; "
                       "a scene file, --set, --fps, --format, --out and --force cannot go with "
                       "it (--duration, --threads, --checkpoint-every, --quiet and --render can)\n",
                       run.resume.c_str());
          return static_cast<int>(kExitBadInput);
        }
      } else if (run.scene.empty()) {
        std::fprintf(stderr, "error: run: expected a scene file (or --resume DIR)\n");
        return static_cast<int>(kExitBadInput);
      }
      if (!duration.empty()) run.overrides.push_back("time.duration=" + duration);
      if (!fps.empty()) run.overrides.push_back("output.fps=" + fps);
      if (!format.empty()) run.overrides.push_back("output.format=" + format);
      if (run.render && !rendererBuilt()) return renderCommand({});  // says why, before running
      if (run.surface && !surfaceBuilt()) return surfaceCommand({});
      return runCommand(run);
    }
    if (*validateCmd) return validateCommand(validateScene, validateOverrides);
    if (*infoCmd) return infoCommand();
    if (*plotCmd) return plotCommand(plot);
    if (*renderCmd) return renderCommand(render);
    if (*surfaceCmd) return surfaceCommand(surface);
    if (*viewCmd) return viewCommand(view);
    if (*benchCmd) return benchCommand(bench);
    return static_cast<int>(kExitBadInput);
  };

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  try {
    return dispatch();
  } catch (const sph::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kExitBadInput;
  } catch (const sph::OutputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kExitOutputFailed;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
