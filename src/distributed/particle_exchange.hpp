// Particles between ranks: migration (each particle to the rank that now owns it, with every
// field and its stable id) and the halo (copies of the particles within a support radius of
// another rank's, for the passes that read neighbours there). A particle travels as a record:
// its id and a fixed number of 32-bit values (position, velocity, density, ... as the step
// packs them; integers travel as their bits).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "distributed/communicator.hpp"

namespace sph::distributed {

struct ParticleRecords {
  int width = 0;  // values per particle; the first three are its position
  std::vector<std::uint32_t> id;
  std::vector<float> value;  // width per particle

  std::size_t size() const { return id.size(); }
  const float* of(std::size_t i) const { return value.data() + i * std::size_t(width); }
  void append(const ParticleRecords& from, std::size_t i);
  // Into id order: the order a rank's particles are kept in, whichever rank sent them.
  void sortById();
};

// Record i as bytes (its id, then its values) at the end of `out`; and the records of such
// bytes appended to `into` (of the same width). Throws std::runtime_error on a partial record.
void packRecord(const ParticleRecords& records, std::size_t i, std::vector<std::byte>& out);
void unpackRecords(const std::vector<std::byte>& bytes, ParticleRecords& into);

// Sends each record to owner[i] and returns what this rank owns afterwards, in id order.
// Collective. Throws std::invalid_argument when owner's size or a rank in it is wrong.
ParticleRecords migrate(const Communicator& comm, const ParticleRecords& records,
                        const std::vector<int>& owner);

struct Box {
  std::array<float, 3> min{0, 0, 0}, max{0, 0, 0};
  bool empty = true;
};

// Which of a rank's records go to which rank as halo: each record within `reach` of another
// rank's region (the bounding box of the particles it owns, which every rank shares here) goes
// there. Holds indices into the records it was planned on, in their order.
struct HaloPlan {
  std::vector<std::vector<std::uint32_t>> send;  // by destination rank
  std::vector<Box> regions;                      // every rank's, by rank
  std::size_t sent() const;
};

// Collective.
HaloPlan planHalo(const Communicator& comm, const ParticleRecords& owned, float reach);

// The halo this rank receives under `plan`, from records laid out as the plan's (the same
// particles in the same order; any width): by source rank, each in its sender's order.
// Collective.
ParticleRecords exchangeHalo(const Communicator& comm, const HaloPlan& plan,
                             const ParticleRecords& owned);

}  // namespace sph::distributed
