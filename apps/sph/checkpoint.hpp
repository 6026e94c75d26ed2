// Checkpoints of a run (sph run --checkpoint-every T, sph run --resume DIR):
// DIR/checkpoints/checkpoint_NNNNN.sphck, NNNNN the frame it was taken at. A checkpoint holds
// the run's resolved scene, where its outputs stood (the frames, the bytes of stats.csv and
// probes.csv, the frames.pvd series) and the simulation's whole state (Simulation::saveState),
// the lot under one checksum. Each is written aside and renamed into place, so a run killed
// at any moment leaves only whole checkpoints; the last two are kept.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "checkpoint_file.hpp"
#include "sph/simulation.hpp"

namespace sph::cli {

std::filesystem::path checkpointDir(const std::filesystem::path& runDir);

// A checkpoint of `sim` at `position`, made now and written by storeCheckpoint; `reached`: how
// far the run will have gone when it is written (the time of `sim`, or later).
struct PendingCheckpoint {
  int frame = 0;
  std::string bytes;
};
PendingCheckpoint makeCheckpoint(const Simulation& sim, const RunPosition& position,
                                 double checkpointEvery, double reached);
// Writes it and removes all but the newest two. Throws OutputError naming the file.
void storeCheckpoint(const std::filesystem::path& runDir, const PendingCheckpoint& checkpoint);

// Both at once: the checkpoint of `sim` as it is now.
void writeCheckpoint(const std::filesystem::path& runDir, const Simulation& sim,
                     const RunPosition& position, double checkpointEvery);

// The newest checkpoint of the run in `runDir`. Throws InputError naming the file and saying
// why when there is none, or the newest is corrupted, cut short or from another version of sph.
Checkpoint readLatestCheckpoint(const std::filesystem::path& runDir);

}  // namespace sph::cli
