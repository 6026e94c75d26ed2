// Progress of a long run: a bar redrawn in place on a terminal, plain lines every few
// seconds when the output is a file or a pipe.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>

namespace sph::cli {

class Progress {
 public:
  Progress(double endTime, bool enabled);
  void update(double simTime, std::uint64_t steps);
  void finish(double simTime, std::uint64_t steps);

 private:
  void print(double simTime, std::uint64_t steps, bool final);

  double endTime_;
  bool enabled_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point lastPrint_;
};

}  // namespace sph::cli
