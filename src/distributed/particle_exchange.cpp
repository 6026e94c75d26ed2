#include "distributed/particle_exchange.hpp"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <string>

namespace sph::distributed {

namespace {

float distanceSquaredToBox(const float* p, const Box& b) {
  float d2 = 0.0f;
  for (int c = 0; c < 3; ++c) {
    const float below = b.min[c] - p[c], above = p[c] - b.max[c];
    const float d = std::max({below, above, 0.0f});
    d2 += d * d;
  }
  return d2;
}

}  // namespace

// A record as bytes: its id, then its values.
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
  for (std::size_t at = 0; at < bytes.size(); at += stride) {
    std::uint32_t id = 0;
    std::memcpy(&id, bytes.data() + at, sizeof id);
    into.id.push_back(id);
    const std::size_t v = into.value.size();
    into.value.resize(v + std::size_t(into.width));
    std::memcpy(into.value.data() + v, bytes.data() + at + sizeof id, valueBytes);
  }
}

void ParticleRecords::append(const ParticleRecords& from, std::size_t i) {
  id.push_back(from.id[i]);
  value.insert(value.end(), from.of(i), from.of(i) + from.width);
}

void ParticleRecords::sortById() {
  std::vector<std::size_t> order(size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return id[a] < id[b]; });
  ParticleRecords sorted;
  sorted.width = width;
  sorted.id.reserve(size());
  sorted.value.reserve(value.size());
  for (std::size_t i : order) sorted.append(*this, i);
  *this = std::move(sorted);
}

ParticleRecords migrate(const Communicator& comm, const ParticleRecords& records,
                        const std::vector<int>& owner) {
  if (owner.size() != records.size())
    throw std::invalid_argument("migrate: " + std::to_string(owner.size()) + " owners for " +
                                std::to_string(records.size()) + " particles");
  std::vector<std::vector<std::byte>> send(std::size_t(comm.size()));
  for (std::size_t i = 0; i < records.size(); ++i) {
    if (owner[i] < 0 || owner[i] >= comm.size())
      throw std::invalid_argument("migrate: particle " + std::to_string(records.id[i]) +
                                  " sent to rank " + std::to_string(owner[i]) + " of " +
                                  std::to_string(comm.size()));
    packRecord(records, i, send[std::size_t(owner[i])]);
  }
  ParticleRecords out;
  out.width = records.width;
  for (const std::vector<std::byte>& bytes : comm.exchange(send)) unpackRecords(bytes, out);
  out.sortById();
  return out;
}

std::size_t HaloPlan::sent() const {
  std::size_t n = 0;
  for (const auto& to : send) n += to.size();
  return n;
}

HaloPlan planHalo(const Communicator& comm, const ParticleRecords& owned, float reach) {
  // This rank's region, shared: min x, y, z, max x, y, z, and 1 when it owns nothing.
  Box mine;
  for (std::size_t i = 0; i < owned.size(); ++i) {
    const float* p = owned.of(i);
    for (int c = 0; c < 3; ++c) {
      mine.min[c] = mine.empty ? p[c] : std::min(mine.min[c], p[c]);
      mine.max[c] = mine.empty ? p[c] : std::max(mine.max[c], p[c]);
    }
    mine.empty = false;
  }
  const std::vector<float> all =
      comm.allgather({mine.min[0], mine.min[1], mine.min[2], mine.max[0], mine.max[1], mine.max[2],
                      mine.empty ? 1.0f : 0.0f});
  HaloPlan plan;
  plan.send.resize(std::size_t(comm.size()));
  plan.regions.resize(std::size_t(comm.size()));
  for (std::size_t r = 0; r < plan.regions.size(); ++r) {
    Box& b = plan.regions[r];
    for (int c = 0; c < 3; ++c) {
      b.min[c] = all[7 * r + std::size_t(c)];
      b.max[c] = all[7 * r + 3 + std::size_t(c)];
    }
    b.empty = all[7 * r + 6] != 0.0f;
  }
  const float reach2 = reach * reach;
  for (std::size_t r = 0; r < plan.regions.size(); ++r) {
    if (int(r) == comm.rank() || plan.regions[r].empty) continue;
    for (std::size_t i = 0; i < owned.size(); ++i)
      if (distanceSquaredToBox(owned.of(i), plan.regions[r]) <= reach2)
        plan.send[r].push_back(std::uint32_t(i));
  }
  return plan;
}

ParticleRecords exchangeHalo(const Communicator& comm, const HaloPlan& plan,
                             const ParticleRecords& owned) {
  std::vector<std::vector<std::byte>> send(std::size_t(comm.size()));
  for (std::size_t r = 0; r < send.size(); ++r)
    for (std::uint32_t i : plan.send[r]) {
      if (i >= owned.size())
        throw std::invalid_argument("exchangeHalo: the plan names particle " + std::to_string(i) +
                                    " of " + std::to_string(owned.size()));
      packRecord(owned, i, send[r]);
    }
  ParticleRecords halo;
  halo.width = owned.width;
  for (const std::vector<std::byte>& bytes : comm.exchange(send)) unpackRecords(bytes, halo);
  return halo;
}

}  // namespace sph::distributed
