// sph run: simulate a scene, writing frames at the scene's frame rate (independent of the
// adaptive time step), one stats row per frame, and a summary at the end.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "checkpoint.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "report.hpp"
#include "run_output.hpp"
#include "run_processes.hpp"
#include "scene_engine.hpp"
#include "sph/error.hpp"
#include "sph/io/frame_writer.hpp"
#include "sph/scene_file.hpp"
#include "sph/simulation.hpp"
#include "sph/threads.hpp"

namespace sph::cli {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct RunRecord {
  nlohmann::json failure;  // null when the run completed
  double wallSeconds = 0.0;
  std::uint64_t firstStep = 0;  // the step this process started from (a resumed run's)
  nlohmann::json resumedFrom;   // the checkpoint, or null
};

// `final`: the statistics now (Simulation::stats, every process's in a run across several).
void writeSummary(const RunOutput& output, const Simulation& sim, const RunRecord& record,
                  double startTime, const FrameStats& final, const RunProcesses& processes) {
  const double simulatedHere = sim.time() - startTime;
  const double steps = double(sim.stepCount() - record.firstStep);
  nlohmann::json summary = {
      {"status", record.failure.is_null()                           ? "completed"
                 : record.failure.value("quantity", "") == "output" ? "output failed"
                                                                    : "failed"},
      {"failure", record.failure},
      {"scene_file", sim.scene().sourcePath},
      {"backend", sim.backendName()},
      {"threads", threadCount()},
      {"calibration", calibrationJson(sim.calibration())},
      {"simulated_time", sim.time()},
      {"steps", sim.stepCount()},
      {"frames", output.framesWritten()},
      {"format", formatName(sim.scene().output.format)},
      {"wall_seconds", record.wallSeconds},
      {"ms_per_step", steps > 0 ? 1000.0 * record.wallSeconds / steps : 0.0},
      {"real_time_factor", record.wallSeconds > 0 ? simulatedHere / record.wallSeconds : 0.0},
      {"resumed_from", record.resumedFrom},
      {"removed_count", sim.removedCount()},
      {"clamped_count", final.clampedCount},
      {"leaked_count", sim.leakedCount()},
      {"emitted_count", sim.emittedCount()},
      {"emitters", flowJson(sim.emitterStats())},
      {"outlets", flowJson(sim.outletStats())},
      {"objects", objectsJson(sim.objectStats())},
      {"final", statsJson(final)},
      {"distributed", processes.summary()},
      {"scene", nlohmann::json::parse(sceneToJsonText(sim.scene()))}};
  io::writeFileAtomically(output.dir() / "summary.json",
                          [&](std::ostream& out) { out << summary.dump(2) << '\n'; });
}

// A resumed run's scene is the one its checkpoint holds, its end time moved by --duration.
Scene sceneOf(const RunOptions& options, const std::optional<Checkpoint>& resumed) {
  if (!resumed) return loadScene(options.scene, options.overrides);
  Scene scene = parseScene(resumed->scene.dump(), resumed->sceneFile, options.overrides);
  const double at = resumed->reached;
  if (scene.time.duration <= at)
    throw InputError(resumed->file.string() + ": time.duration: the run already reached t = " +
                     formatNumber(at) + " s; expected a longer --duration to extend it");
  return scene;
}

// Another process failed and process 0 has said why: this one ends with the run's code.
struct ProcessGroupFailed {
  int code;
};

// Process 0 makes the run's directory (or says why it cannot); the others then find it made.
void makeOutput(std::optional<RunOutput>& output, const std::string& dir, const Scene& scene,
                bool force, const std::vector<std::string>& objectNames,
                const RunProcesses& processes) {
  const RunPiece piece{processes.rank(), processes.ranks()};
  if (!processes.divided()) {
    output.emplace(dir, scene.output.format, force, objectNames, piece);
    return;
  }
  std::exception_ptr error;
  bool badInput = false;
  if (processes.lead()) {
    try {
      output.emplace(dir, scene.output.format, force, objectNames, piece);
    } catch (const InputError&) {
      error = std::current_exception();
      badInput = true;
    } catch (const std::exception&) {
      error = std::current_exception();
    }
  }
  const bool inputFailed = processes.any(badInput);
  const bool failed = processes.any(error != nullptr);
  if (error) std::rethrow_exception(error);
  if (failed) throw ProcessGroupFailed{inputFailed ? kExitBadInput : kExitOutputFailed};
  if (!processes.lead()) output.emplace(dir, scene.output.format, force, objectNames, piece);
}

int runScene(const RunOptions& options, RunProcesses& processes);

}  // namespace

int runCommand(const RunOptions& options) {
  RunProcesses processes(options);
  try {
    return runScene(options, processes);
  } catch (const ProcessGroupFailed& failed) {
    return failed.code;
  } catch (const std::exception&) {
    // Every process meets bad input alike: process 0 says so, the others end with its code.
    if (processes.lead()) throw;
    return kExitBadInput;
  }
}

namespace {

int runScene(const RunOptions& options, RunProcesses& processes) {
  if (processes.divided() && (!options.resume.empty() || options.checkpointEvery > 0.0))
    throw InputError(
        "run: --checkpoint-every and --resume: a run across processes keeps no checkpoints "
        "yet; run it in one process to keep them");
  const bool quiet = options.quiet || !processes.lead();
  setThreadCount(options.threads);
  std::optional<Checkpoint> resumed;
  if (!options.resume.empty()) resumed = readLatestCheckpoint(options.resume);
  const Scene scene = sceneOf(options, resumed);
  // A scene without a name writes under its file's name; the loader keeps names to one path
  // component, so the run stays inside out/.
  const std::string name =
      scene.name.empty() ? std::filesystem::path(options.scene).stem().string() : scene.name;
  const std::string dir = resumed               ? options.resume
                          : options.out.empty() ? "out/" + name
                                                : options.out;
  const int device = processes.device(options.device);
  Simulation sim(scene, simulationOptions(options.backend, device));
  const std::unique_ptr<cli::SceneEngine> sceneEngine = cli::attachSceneEngine(scene, sim);
  processes.distribute(sim);
  if (sceneEngine && (resumed || options.checkpointEvery > 0.0))
    throw InputError(scene.sourcePath +
                     ": object_engine.type: \"bullet\" runs keep no checkpoints (Bullet's "
                     "world is not saved with the fluid); expected no --checkpoint-every or "
                     "--resume");
  if (resumed) {
    std::istringstream state(resumed->state);
    try {
      sim.loadState(state);
    } catch (const InputError& e) {
      throw InputError(resumed->file.string() + ": " + e.what());
    }
  }
  const double startTime = sim.time();
  std::vector<std::string> objectNames;
  for (const ObjectDesc& object : scene.objects) objectNames.push_back(object.name);
  std::optional<RunOutput> outputs;
  if (resumed)
    outputs.emplace(dir, scene.output.format, objectNames, resumed->position, sim.stats());
  else
    makeOutput(outputs, dir, scene, options.force, objectNames, processes);
  RunOutput& output = *outputs;
  // Checkpoints go on at the resumed run's interval unless asked otherwise.
  const double checkpointEvery = options.checkpointEvery > 0.0 ? options.checkpointEvery
                                 : resumed                     ? resumed->checkpointEvery
                                                               : 0.0;
  if (!quiet) {
    printCalibration(stdout, sim);
    if (std::string(sim.backendName()) == "cuda") {
      std::printf("  backend              cuda, device %d%s\n", device,
                  processes.divided() ? " (process 0's; each its own)" : "");
      // The 2021 CUDA SPH tutorial's memory report: what the GPU holds and has free.
      printGpus(stdout);
    } else {
      std::printf("  backend              cpu, %d threads\n", threadCount());
    }
    if (processes.divided())
      std::printf("  processes            %d (mpirun), partition %s, again past %gx drift\n",
                  processes.ranks(), options.partition.c_str(), options.rebalanceAt);
    std::printf("writing %s frames at %g per second to %s\n", formatName(scene.output.format),
                scene.output.fps, output.dir().c_str());
    std::fflush(stdout);
  }

  const double endTime = scene.time.duration;
  const double framePeriod = 1.0 / scene.output.fps;
  const auto start = Clock::now();
  RunRecord record;
  record.firstStep = sim.stepCount();
  if (resumed)
    record.resumedFrom = {
        {"checkpoint", resumed->file.string()}, {"time", startTime}, {"step", record.firstStep}};
  Progress progress(endTime, !quiet);
  auto lastFrameWall = Clock::now();
  std::uint64_t lastFrameSteps = sim.stepCount();
  auto writeFrame = [&] {
    const std::uint64_t steps = sim.stepCount() - lastFrameSteps;
    const double wallMsPerStep = steps ? 1000.0 * secondsSince(lastFrameWall) / double(steps) : 0.0;
    output.writeFrame(sim.capture(), wallMsPerStep);  // objects move: they are in every frame
    output.writeProbes(sim.probeColumns(), sim.takeProbeRows());
    lastFrameWall = Clock::now();
    lastFrameSteps = sim.stepCount();
  };

  // After a frame: the first frame in each new interval k T <= t < (k + 1) T, and the last.
  // Counted in whole intervals (with room for rounding), so that a resumed run and one never
  // interrupted take theirs at the same frames.
  const auto interval = [&](double t) {
    return std::floor(t / checkpointEvery * (1.0 + 1e-12) + 1e-9);
  };
  double lastCheckpoint = startTime;
  auto checkpointIfDue = [&] {
    if (checkpointEvery <= 0.0) return;
    if (interval(sim.time()) <= interval(lastCheckpoint) && sim.time() < endTime) return;
    writeCheckpoint(output.dir(), sim, output.position(), checkpointEvery);
    lastCheckpoint = sim.time();
  };

  // A run that ends between two frames keeps the checkpoint of its last frame at a whole frame
  // period, not of its end: a step lands on each frame's time, so a run stopped there and
  // extended with --resume --duration takes the steps of one never stopped.
  std::optional<PendingCheckpoint> lastWholeFrame;

  const int firstFrame = resumed ? resumed->position.frame + 1 : 1;
  try {
    if (!resumed) {
      if (processes.lead()) {
        output.writeBoundary(sim.boundaryFrame());
        output.writeObjectSurfaces(sim.objectSurfaces());
      }
      writeFrame();
    }
    for (int frame = firstFrame; sim.time() < endTime; ++frame) {
      const double frameTime = std::min(frame * framePeriod, endTime);
      const bool cutShort = frameTime != frame * framePeriod;  // the last, between two frames
      if (cutShort && checkpointEvery > 0.0)
        lastWholeFrame = makeCheckpoint(sim, output.position(), checkpointEvery, endTime);
      while (sim.time() < frameTime) {
        sim.step(frameTime);
        if (sceneEngine) sceneEngine->step();
        progress.update(sim.time(), sim.stepCount());
      }
      writeFrame();
      if (lastWholeFrame)
        storeCheckpoint(output.dir(), *lastWholeFrame);
      else
        checkpointIfDue();
    }
  } catch (const SimulationFailure& failure) {
    output.finish();  // the frames before the failure are kept
    output.writeProbes(sim.probeColumns(), sim.takeProbeRows());
    progress.finish(sim.time(), sim.stepCount());
    record.wallSeconds = secondsSince(start);
    record.failure = {{"message", failure.what()},
                      {"step", failure.step()},
                      {"particle", failure.particleId()},
                      {"quantity", failure.quantity()}};
    // Every process fails at the same step (the failure check reads every process's).
    const FrameStats final = sim.stats();
    processes.barrier();  // every piece written
    if (!processes.lead()) return kExitSimulationFailed;
    writeSummary(output, sim, record, startTime, final, processes);
    std::fprintf(stderr, "error: %s\nthe frames and stats up to t = %g s are in %s\n",
                 failure.what(), sim.time(), output.dir().c_str());
    return kExitSimulationFailed;
  } catch (const OutputError& failure) {
    if (processes.divided()) {
      // This process's disk alone: the others would wait for it at the next step.
      std::fprintf(stderr, "error: process %d: %s\nthe run stopped at t = %g s\n", processes.rank(),
                   failure.what(), sim.time());
      processes.abort(kExitOutputFailed);
    }
    // The frames written are whole (each is renamed into place); say what happened in
    // summary.json if the disk still takes it.
    progress.finish(sim.time(), sim.stepCount());
    record.wallSeconds = secondsSince(start);
    record.failure = {{"message", failure.what()}, {"quantity", "output"}};
    bool summarised = true;
    try {
      writeSummary(output, sim, record, startTime, sim.stats(), processes);
    } catch (const std::exception&) {
      summarised = false;
    }
    std::fprintf(stderr, "error: %s\nthe run stopped at t = %g s; %s\n", failure.what(), sim.time(),
                 summarised ? "summary.json says so" : "summary.json could not be written either");
    return kExitOutputFailed;
  }
  output.finish();
  progress.finish(sim.time(), sim.stepCount());
  record.wallSeconds = secondsSince(start);
  const FrameStats last = sim.stats();
  processes.barrier();  // every piece written
  if (!processes.lead()) return kExitOk;
  writeSummary(output, sim, record, startTime, last, processes);
  if (!quiet) {
    std::printf(
        "done: %llu steps, %.3f ms per step, %d frames; %llu fluid particles left, "
        "%llu removed, %llu leaked\n",
        static_cast<unsigned long long>(sim.stepCount()),
        1000.0 * record.wallSeconds /
            double(std::max<std::uint64_t>(sim.stepCount() - record.firstStep, 1)),
        output.framesWritten(), static_cast<unsigned long long>(last.fluidCount),
        static_cast<unsigned long long>(last.removedCount),
        static_cast<unsigned long long>(last.leakedCount));
    if (last.emittedCount > 0 || !sim.scene().outlets.empty()) {
      std::uint64_t drained = 0;
      for (const FlowStats& f : sim.outletStats()) drained += f.particles;
      std::printf("flow: %llu particles emitted, %llu drained by the outlets\n",
                  static_cast<unsigned long long>(last.emittedCount),
                  static_cast<unsigned long long>(drained));
    }
    if (last.boundaryCount > 0) {
      std::printf(
          "open %s/frames.pvd (and the walls, %s/boundary.vtp) in ParaView; statistics "
          "in %s/stats.csv\n",
          output.dir().c_str(), output.dir().c_str(), output.dir().c_str());
    } else {
      std::printf("open %s/frames.pvd in ParaView; statistics in %s/stats.csv\n",
                  output.dir().c_str(), output.dir().c_str());
    }
    if (!sim.probeColumns().empty())
      std::printf("probes at %g per second in %s/probes.csv\n", scene.output.probeRate,
                  output.dir().c_str());
  }
  if (options.surface) {
    SurfaceOptions surface;
    surface.dir = output.dir().string();
    surface.quiet = options.quiet;
    const int status = surfaceCommand(surface);
    if (status != kExitOk) return status;
  }
  if (options.render) {
    RenderOptions render;
    render.dir = output.dir().string();
    render.quiet = options.quiet;
    return renderCommand(render);
  }
  return kExitOk;
}

}  // namespace

}  // namespace sph::cli
