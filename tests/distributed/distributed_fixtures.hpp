// Particles spread over the ranks as a distributed run starts: a lattice of ids 0..n-1, each
// rank holding every size-th one, with values that say whose they are.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "distributed/communicator.hpp"
#include "distributed/particle_exchange.hpp"

namespace sph::distributed::test {

constexpr int kSide = 24;  // a 24³ block: 13,824 particles
constexpr float kSpacing = 0.01f;
constexpr int kWidth = 5;  // position, id × 0.5, and the id's own bits

inline void lattice(std::uint32_t id, float* p) {
  p[0] = kSpacing * float(id % kSide);
  p[1] = kSpacing * float((id / kSide) % kSide);
  p[2] = kSpacing * float(id / (kSide * kSide));
}

inline void fill(std::uint32_t id, float* v) {
  lattice(id, v);
  v[3] = 0.5f * float(id);
  std::memcpy(&v[4], &id, sizeof id);
}

// Whether a record's values are those its id was given: bit for bit, as the transport copies
// them.
inline bool intact(const ParticleRecords& r, std::size_t i) {
  float expected[kWidth];
  fill(r.id[i], expected);
  return std::memcmp(expected, r.of(i), sizeof expected) == 0;
}

inline ParticleRecords scattered(const Communicator& comm) {
  ParticleRecords r;
  r.width = kWidth;
  const std::uint32_t n = kSide * kSide * kSide;
  for (std::uint32_t id = std::uint32_t(comm.rank()); id < n; id += std::uint32_t(comm.size())) {
    r.id.push_back(id);
    r.value.resize(r.value.size() + kWidth);
    fill(id, r.value.data() + r.value.size() - kWidth);
  }
  return r;
}

inline std::vector<float> positions(const ParticleRecords& r) {
  std::vector<float> p;
  for (std::size_t i = 0; i < r.size(); ++i) p.insert(p.end(), r.of(i), r.of(i) + 3);
  return p;
}

}  // namespace sph::distributed::test
