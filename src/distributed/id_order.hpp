// Particles into id order in linear time: a distributed step sorts each process's particles so
// every process lists a cell's particles as one process would.
#pragma once

#include <cstdint>
#include <vector>

namespace sph::distributed {

// The indices of `ids` in increasing order of id, the ghost bit (fluid::kGhostBit) ignored;
// stable among equal ids. Two passes of a 16-bit radix sort.
std::vector<std::uint32_t> orderById(const std::vector<std::uint32_t>& ids);

}  // namespace sph::distributed
