// The sph subcommands (DESIGN.md's command-line contract). Each returns the process exit code:
// 0 done, 2 bad input, 3 the simulation failed.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "sph/simulation.hpp"

namespace sph::cli {

enum ExitCode { kExitOk = 0, kExitBadInput = 2, kExitSimulationFailed = 3 };

struct RunOptions {
  std::string scene;
  std::string out;              // default: out/<scene name>
  std::string backend = "cpu";  // until the GPU engine has run on a GPU (docs/gpu.md)
  int threads = 0;              // 0: all hardware threads
  int device = 0;               // CUDA device
  std::vector<std::string> overrides;
  bool force = false;
  bool quiet = false;
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
  // Seed 1 §9: each scene with objects is timed at each of these influence ratios.
  std::vector<double> influenceRatios;
};

int runCommand(const RunOptions& options);
int validateCommand(const std::string& scene, const std::vector<std::string>& overrides);
int infoCommand();
int benchCommand(const BenchOptions& options);

// The options that choose where a Simulation runs. "cuda" without a usable GPU makes the
// Simulation throw an InputError that says why; "auto" takes the GPU when there is one.
SimulationOptions simulationOptions(const std::string& backend, int device);

// One line per GPU: name, compute capability, memory (total and free), for `sph info` and
// the start of a GPU run.
void printGpus(std::FILE* out);

}  // namespace sph::cli
