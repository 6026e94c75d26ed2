#include "distributed/particle_exchange.hpp"

#include <cstring>
#include <stdexcept>
#include <string>

namespace sph::distributed {

void packRecord(const ParticleRecords& r, std::size_t i, std::vector<std::byte>& out) {
  const std::size_t at = out.size();
  const std::size_t valueBytes = std::size_t(r.width) * sizeof(float);
  out.resize(at + sizeof(std::uint32_t) + valueBytes);
  std::memcpy(out.data() + at, &r.id[i], sizeof(std::uint32_t));
  std::memcpy(out.data() + at + sizeof(std::uint32_t), r.of(i), valueBytes);
}

void unpackRecords(const std::vector<std::byte>& bytes, ParticleRecords& into) {
  const std::size_t valueBytes = std::size_t(into.width) * sizeof(float);
  const std::size_t stride = sizeof(std::uint32_t) + valueBytes;
  if (bytes.size() % stride != 0)
    throw std::runtime_error("particle exchange: received " + std::to_string(bytes.size()) +
                             " bytes, not whole records of " + std::to_string(stride));
  const std::size_t count = bytes.size() / stride;
  const std::size_t first = into.size();
  into.id.resize(first + count);
  into.value.resize((first + count) * std::size_t(into.width));
  for (std::size_t k = 0; k < count; ++k) {
    const std::byte* at = bytes.data() + k * stride;
    std::memcpy(&into.id[first + k], at, sizeof(std::uint32_t));
    std::memcpy(into.value.data() + (first + k) * std::size_t(into.width),
                at + sizeof(std::uint32_t), valueBytes);
  }
}

}  // namespace sph::distributed
