// Particles as they travel between ranks: a record of the stable id and a fixed number of
// 32-bit values (position, velocity, density, ... as the step packs them; integers travel as
// their bits), packed into the byte buffers Communicator::exchange carries.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sph::distributed {

struct ParticleRecords {
  int width = 0;  // values per particle; the first three are its position
  std::vector<std::uint32_t> id;
  std::vector<float> value;  // width per particle

  std::size_t size() const { return id.size(); }
  const float* of(std::size_t i) const { return value.data() + i * std::size_t(width); }
};

// Record i as bytes (its id, then its values) at the end of `out`; and the records of such
// bytes appended to `into` (of the same width). Throws std::runtime_error on a partial record.
void packRecord(const ParticleRecords& records, std::size_t i, std::vector<std::byte>& out);
void unpackRecords(const std::vector<std::byte>& bytes, ParticleRecords& into);

}  // namespace sph::distributed
