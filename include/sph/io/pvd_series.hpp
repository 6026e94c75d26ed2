// A ParaView collection (.pvd) that lists a run's frames with their times, so ParaView plays them
// against simulated time rather than frame number.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace sph::io {

class PvdSeries {
 public:
  // Nothing is written until the first add.
  explicit PvdSeries(std::filesystem::path pvdFile);
  // A resumed run's: the frames its checkpoint listed (time, file), written again at the next add.
  PvdSeries(std::filesystem::path pvdFile, std::vector<std::pair<double, std::string>> frames);
  std::vector<std::pair<double, std::string>> frames() const;

  // Appends a frame (`relativeFile` relative to the .pvd's folder) and rewrites the whole
  // collection atomically, so the .pvd on disk is valid after every frame even if the run dies.
  // Throws OutputError naming the path when it cannot be written.
  void add(double time, const std::string& relativeFile);

 private:
  struct Entry {
    double time;
    std::string file;
  };

  std::filesystem::path pvdFile_;
  std::vector<Entry> entries_;
};

}  // namespace sph::io
