// The experiments' records in tests/data/: '#' comments, a header line starting "T", then one
// "T,value" pair a line, read into Point{T, value}.
#pragma once

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace sph::testing {

template <class Point>
std::vector<Point> readTestData(const std::string& name) {
  std::ifstream in(std::string(SPH_SOURCE_DIR) + "/tests/data/" + name);
  std::vector<Point> points;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'T') continue;
    std::istringstream fields(line);
    double t = 0.0, value = 0.0;
    char comma = 0;
    if (fields >> t >> comma >> value) points.push_back(Point{t, value});
  }
  return points;
}

}  // namespace sph::testing
