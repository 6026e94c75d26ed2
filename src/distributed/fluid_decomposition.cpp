#include "distributed/fluid_decomposition.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include "distributed/particle_exchange.hpp"
#include "fluid/build_grid.hpp"
#include "sph/core/grid.hpp"

namespace sph::distributed {

namespace {

// A particle's record: position, velocity, acceleration (4 floats each), density, pressure,
// its work, and the incompressible solver's warm start (4) where it runs.
constexpr int kFields = 15;
constexpr int kWork = 14;
constexpr int kWarmStartFields = 4;

// A particle's work: the neighbours its last density pass listed, one for none (a lone
// particle still costs its walk), and a full neighbourhood's worth past the list's room.
float workOf(const sim::HostFluidState& s, std::size_t i) {
  if (s.neighbours.size() <= i) return 1.0f;
  const std::uint32_t n = s.neighbours[i];
  return n == fluid::kNeighborOverflow ? 128.0f : float(n > 0 ? n : 1);
}

// The rows' records, in their order: the state's particle ids (ghost bit clear) and fields.
ParticleRecords packRows(const sim::HostFluidState& s, const std::vector<std::uint32_t>& rows) {
  const sim::HostParticles& p = s.particles;
  ParticleRecords out;
  out.width = kFields + (s.warmStart.empty() ? 0 : kWarmStartFields);
  out.id.resize(rows.size());
  out.value.resize(rows.size() * std::size_t(out.width));
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::size_t i = rows[k];
    out.id[k] = p.id[i] & ~fluid::kGhostBit;
    float* v = out.value.data() + k * std::size_t(out.width);
    std::memcpy(v, &p.position[i], sizeof(Vec4));
    std::memcpy(v + 4, &p.velocity[i], sizeof(Vec4));
    std::memcpy(v + 8, &p.acceleration[i], sizeof(Vec4));
    v[12] = p.density[i];
    v[13] = p.pressure[i];
    v[kWork] = workOf(s, i);
    if (!s.warmStart.empty()) std::memcpy(v + kFields, &s.warmStart[i], sizeof(Vec4));
  }
  return out;
}

std::vector<float> workOf(const ParticleRecords& r) {
  std::vector<float> work(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) work[i] = r.of(i)[kWork];
  return work;
}

// Keeps the records whose `stays` is set, in their order, moving each at most once.
void keepOnly(ParticleRecords& r, const std::vector<int>& owner, int me) {
  const std::size_t width = std::size_t(r.width);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (owner[i] != me) continue;
    if (kept != i) {
      r.id[kept] = r.id[i];
      std::memcpy(r.value.data() + kept * width, r.of(i), width * sizeof(float));
    }
    ++kept;
  }
  r.id.resize(kept);
  r.value.resize(kept * width);
}

// The records into the state's arrays: the owned, then the ghosts with their ids marked.
void writeState(sim::HostFluidState& s, const ParticleRecords& owned,
                const ParticleRecords& ghosts) {
  sim::HostParticles& p = s.particles;
  const std::size_t n = owned.size() + ghosts.size();
  const bool warm = !s.warmStart.empty();
  p.id.resize(n);
  p.position.resize(n);
  p.velocity.resize(n);
  p.acceleration.resize(n);
  p.density.resize(n);
  p.pressure.resize(n);
  if (warm) s.warmStart.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const bool ghost = k >= owned.size();
    const ParticleRecords& from = ghost ? ghosts : owned;
    const std::size_t i = ghost ? k - owned.size() : k;
    const float* v = from.of(i);
    p.id[k] = from.id[i] | (ghost ? fluid::kGhostBit : 0u);
    std::memcpy(&p.position[k], v, sizeof(Vec4));
    std::memcpy(&p.velocity[k], v + 4, sizeof(Vec4));
    std::memcpy(&p.acceleration[k], v + 8, sizeof(Vec4));
    p.density[k] = v[12];
    p.pressure[k] = v[13];
    if (warm) std::memcpy(&s.warmStart[k], v + kFields, sizeof(Vec4));
  }
}

std::vector<float> positionsOf(const ParticleRecords& r) {
  std::vector<float> points(3 * r.size());
  for (std::size_t i = 0; i < r.size(); ++i) std::copy(r.of(i), r.of(i) + 3, &points[3 * i]);
  return points;
}

// The bounds of every process's particles.
sim::Exchanged gridBounds(const Communicator& comm, const ParticleRecords& owned) {
  // This process's: min x, y, z, max x, y, z, and 1 where it owns any.
  std::vector<float> mine(7, 0.0f);
  for (std::size_t i = 0; i < owned.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const float x = owned.of(i)[c];
      mine[c] = i == 0 ? x : std::min(mine[c], x);
      mine[3 + c] = i == 0 ? x : std::max(mine[3 + c], x);
    }
  mine[6] = owned.size() != 0 ? 1.0f : 0.0f;
  const std::vector<float> boxes = comm.allgather(mine);
  sim::Exchanged out;
  for (std::size_t r = 0; r < boxes.size(); r += 7) {
    const float* b = &boxes[r];
    if (b[6] == 0.0f) continue;
    const Vec3 lo{b[0], b[1], b[2]}, hi{b[3], b[4], b[5]};
    out.gridLo = out.any ? Vec3{std::min(out.gridLo.x, lo.x), std::min(out.gridLo.y, lo.y),
                                std::min(out.gridLo.z, lo.z)}
                         : lo;
    out.gridHi = out.any ? Vec3{std::max(out.gridHi.x, hi.x), std::max(out.gridHi.y, hi.y),
                                std::max(out.gridHi.z, hi.z)}
                         : hi;
    out.any = true;
  }
  return out;
}

// A particle's cell as the grid pass finds it (fluid/build_grid.hpp).
Int3 cellOf(const GridSpec& grid, const float* x) {
  return clampToGrid(grid, cellCoordinate(grid, Vec3{x[0], x[1], x[2]}));
}

// The cells of a process's particles, as a box of cells; and whether a cell is next to it.
struct CellRange {
  Int3 lo{0, 0, 0}, hi{-1, -1, -1};
  bool empty = true;
  bool touches(Int3 c) const {
    return !empty && c.x >= lo.x - 1 && c.x <= hi.x + 1 && c.y >= lo.y - 1 && c.y <= hi.y + 1 &&
           c.z >= lo.z - 1 && c.z <= hi.z + 1;
  }
};

// Every process's, by rank, from the cells of its particles.
std::vector<CellRange> cellRanges(const Communicator& comm, const std::vector<Int3>& cells) {
  CellRange mine;
  for (const Int3& c : cells) {
    mine.lo = mine.empty ? c
                         : Int3{std::min(mine.lo.x, c.x), std::min(mine.lo.y, c.y),
                                std::min(mine.lo.z, c.z)};
    mine.hi = mine.empty ? c
                         : Int3{std::max(mine.hi.x, c.x), std::max(mine.hi.y, c.y),
                                std::max(mine.hi.z, c.z)};
    mine.empty = false;
  }
  // Cell coordinates are below 2^24: exact as floats.
  const std::vector<float> all =
      comm.allgather({float(mine.lo.x), float(mine.lo.y), float(mine.lo.z), float(mine.hi.x),
                      float(mine.hi.y), float(mine.hi.z), mine.empty ? 1.0f : 0.0f});
  std::vector<CellRange> out(std::size_t(comm.size()));
  for (std::size_t r = 0; r < out.size(); ++r) {
    const float* a = &all[7 * r];
    out[r] = {Int3{int(a[0]), int(a[1]), int(a[2])}, Int3{int(a[3]), int(a[4]), int(a[5])},
              a[6] != 0.0f};
  }
  return out;
}

// What the failure check may name: BadParticle::quantity travels as its index here.
constexpr const char* kQuantities[] = {"density", "acceleration", "velocity",
                                       "compression rho/rho0 - 1", "speed"};

std::uint8_t quantityIndex(const char* quantity) {
  for (std::uint8_t k = 0; k < std::size(kQuantities); ++k)
    if (std::strcmp(kQuantities[k], quantity) == 0) return k;
  return 0;
}

}  // namespace

FluidDecomposition::FluidDecomposition(const Communicator& comm,
                                       const DecompositionSettings& settings)
    : comm_(comm), settings_(settings), partitioner_(comm, settings.method) {
  stats_.ranks = comm.size();
  stats_.rebalanceAt = settings.rebalanceAt;
}

sim::Exchanged FluidDecomposition::exchange(sim::HostFluidState& state,
                                            const sim::ExchangeSettings& settings) {
  const sim::HostParticles& p = state.particles;
  const int ranks = comm_.size(), me = comm_.rank();
  std::vector<std::uint32_t> rows;
  rows.reserve(p.id.size());
  std::uint64_t removed = 0;
  for (std::size_t i = 0; i < p.id.size(); ++i) {
    if (fluid::isGhost(p.id[i])) continue;
    // Before the first partition every process holds every particle: each starts from a share.
    if (!partitioned_ && int(p.id[i] % std::uint32_t(ranks)) != me) continue;
    // Left the domain: the grid would remove it; counted once, by its owner.
    if (!fluid::detail::insideBox(settings.domainMin, settings.domainMax, xyz(p.position[i]))) {
      ++removed;
      continue;
    }
    rows.push_back(std::uint32_t(i));
  }
  ParticleRecords owned = packRows(state, rows);

  // Where each belongs: the kept cuts, or new cuts when the load has drifted.
  const std::vector<float> points = positionsOf(owned);
  const bool cut = !partitioned_ || imbalance_ > settings_.rebalanceAt * balanceWhenCut_;
  if (cut) {
    if (partitioned_) ++stats_.repartitions;
    partitioner_.assign(points, workOf(owned));
    partitioned_ = true;
  }
  // By the cuts alone, also right after cutting: Zoltan's own answer may split the particles
  // on a cut otherwise than its cuts do, and the next step would move them across.
  const std::vector<int> owner = partitioner_.owners(points);

  // Only the particles that cross a cut travel.
  std::vector<std::vector<std::byte>> leaving(static_cast<std::size_t>(ranks));
  std::uint64_t migrated = 0;
  for (std::size_t i = 0; i < owned.size(); ++i)
    if (owner[i] != me) {
      packRecord(owned, i, leaving[std::size_t(owner[i])]);
      ++migrated;
    }
  if (migrated != 0) keepOnly(owned, owner, me);
  for (const std::vector<std::byte>& bytes : comm_.exchange(leaving)) unpackRecords(bytes, owned);

  // The grid spans every process's particles, as one process's would.
  sim::Exchanged out = gridBounds(comm_, owned);

  // The ghosts: every particle in a cell next to one of another process's goes there. Within
  // reach would do for the sums, but the density pass walks whole rows of cells in batches, and
  // a particle out of reach still takes its slot in a batch: the rows must be whole for the
  // sums to group as one process's do.
  const GridSpec grid = makeGrid(out.gridLo, out.gridHi, settings.reach);
  std::vector<Int3> cells(owned.size());
  for (std::size_t i = 0; i < owned.size(); ++i) cells[i] = cellOf(grid, owned.of(i));
  const std::vector<CellRange> ranges = cellRanges(comm_, cells);
  std::vector<std::vector<std::byte>> halo(static_cast<std::size_t>(ranks));
  sentRows_.assign(std::size_t(ranks), {});
  for (std::size_t i = 0; i < owned.size(); ++i)
    for (std::size_t r = 0; r < halo.size(); ++r) {
      if (int(r) == me || !ranges[r].touches(cells[i])) continue;
      packRecord(owned, i, halo[r]);
      sentRows_[r].push_back(std::uint32_t(i));
    }
  ParticleRecords ghosts;
  ghosts.width = owned.width;
  const std::vector<std::vector<std::byte>> arrived = comm_.exchange(halo);
  ghostRows_.assign(std::size_t(ranks) + 1, std::uint32_t(owned.size()));
  for (std::size_t r = 0; r < arrived.size(); ++r) {
    unpackRecords(arrived[r], ghosts);
    ghostRows_[r + 1] = std::uint32_t(owned.size() + ghosts.size());
  }
  writeState(state, owned, ghosts);
  uploaded_ = owned.size() + ghosts.size();

  // The run's figures, in one collective: removed, migrated, work, ghosts over owned.
  double work = 0.0;
  for (std::size_t i = 0; i < owned.size(); ++i) work += owned.of(i)[kWork];
  const std::vector<double> all = comm_.gather(
      std::vector<double>{double(removed), double(migrated), work,
                          owned.size() ? double(ghosts.size()) / double(owned.size()) : 0.0});
  double totalRemoved = 0, stepMigrated = 0, totalWork = 0, busiest = 0, ghostShare = 0;
  for (std::size_t k = 0; k < all.size(); k += 4) {
    totalRemoved += all[k];
    stepMigrated += all[k + 1];
    totalWork += all[k + 2];
    busiest = std::max(busiest, all[k + 2]);
    ghostShare += all[k + 3] / ranks;
  }
  out.removed = std::uint64_t(totalRemoved);
  imbalance_ = totalWork > 0 ? busiest * ranks / totalWork : 1.0;
  if (cut) balanceWhenCut_ = imbalance_;
  ++stats_.exchanges;
  // The first exchange hands out the starting shares: not a migration.
  if (stats_.exchanges > 1) migratedSum_ += stepMigrated;
  ghostShareSum_ += ghostShare;
  stats_.lastImbalance = imbalance_;
  stats_.largestImbalance = std::max(stats_.largestImbalance, imbalance_);
  return out;
}

sim::GhostDensities FluidDecomposition::ghostDensities(const sim::HostDensities& densities) {
  const std::vector<std::uint32_t>& order = densities.gridOrder;
  if (order.size() != uploaded_ || densities.density.size() != uploaded_)
    throw std::logic_error("ghost densities: " + std::to_string(order.size()) +
                           " rows after the grid, " + std::to_string(uploaded_) +
                           " after the last exchange");
  // Where the grid put each row of the state the exchange gave.
  std::vector<std::uint32_t> rowNow(order.size());
  for (std::size_t j = 0; j < order.size(); ++j) rowNow[order[j]] = std::uint32_t(j);
  sentRowsNow_.clear();
  for (const std::vector<std::uint32_t>& rows : sentRows_)
    for (std::uint32_t row : rows) sentRowsNow_.push_back(rowNow[row]);
  ghostRowsNow_.clear();
  for (std::size_t row = ghostRows_.front(); row < uploaded_; ++row)
    ghostRowsNow_.push_back(rowNow[row]);
  std::vector<float> sent(sentRowsNow_.size());
  for (std::size_t k = 0; k < sent.size(); ++k) sent[k] = densities.density[sentRowsNow_[k]];
  return {ghostRowsNow_, exchange(sent, 1)};
}

std::vector<float> FluidDecomposition::exchange(const std::vector<float>& sent,
                                                std::uint32_t width) {
  if (sent.size() != sentRowsNow_.size() * width)
    throw std::logic_error("ghost exchange: " + std::to_string(sent.size()) + " values for " +
                           std::to_string(sentRowsNow_.size()) + " rows of " +
                           std::to_string(width));
  std::vector<std::vector<std::byte>> send(sentRows_.size());
  std::size_t at = 0;
  for (std::size_t r = 0; r < send.size(); ++r) {
    const std::size_t values = sentRows_[r].size() * width;
    send[r].resize(values * sizeof(float));
    if (values) std::memcpy(send[r].data(), sent.data() + at, values * sizeof(float));
    at += values;
  }
  const std::vector<std::vector<std::byte>> arrived = comm_.exchange(send);
  std::vector<float> out(ghostRowsNow_.size() * width);
  at = 0;
  for (std::size_t r = 0; r < arrived.size(); ++r) {
    const std::size_t values = std::size_t(ghostRows_[r + 1] - ghostRows_[r]) * width;
    if (arrived[r].size() != values * sizeof(float))
      throw std::runtime_error("ghost exchange: rank " + std::to_string(r) + " sent " +
                               std::to_string(arrived[r].size()) + " bytes for " +
                               std::to_string(values) + " values");
    if (values) std::memcpy(out.data() + at, arrived[r].data(), values * sizeof(float));
    at += values;
  }
  return out;
}

void FluidDecomposition::reduce(std::uint64_t& sum, std::uint64_t& count, std::uint64_t& largest) {
  sum = comm_.sum(sum);
  count = comm_.sum(count);
  // Errors are below 2^36 in fixed point: exact as doubles.
  largest = std::uint64_t(comm_.max(double(largest)));
}

fluid::StepMeasures FluidDecomposition::combine(const fluid::StepMeasures& local) {
  const std::vector<float> all = comm_.allgather(
      {local.maxSpeed, local.maxAcceleration, local.maxDensityError, local.finite ? 1.0f : 0.0f});
  fluid::StepMeasures out;
  for (std::size_t r = 0; r < all.size(); r += 4) {
    out.maxSpeed = std::max(out.maxSpeed, all[r]);
    out.maxAcceleration = std::max(out.maxAcceleration, all[r + 1]);
    out.maxDensityError = std::max(out.maxDensityError, all[r + 2]);
    out.finite = out.finite && all[r + 3] != 0.0f;
  }
  return out;
}

fluid::BadParticle FluidDecomposition::combine(const fluid::BadParticle& local) {
  // found, pastBound, quantity, then id and value.
  std::vector<std::byte> mine(3 + sizeof(std::uint32_t) + sizeof(float));
  mine[0] = std::byte(local.found ? 1 : 0);
  mine[1] = std::byte(local.pastBound ? 1 : 0);
  mine[2] = std::byte(quantityIndex(local.quantity));
  std::memcpy(mine.data() + 3, &local.id, sizeof local.id);
  std::memcpy(mine.data() + 3 + sizeof local.id, &local.value, sizeof local.value);
  const std::vector<std::vector<std::byte>> all =
      comm_.exchange(std::vector<std::vector<std::byte>>(std::size_t(comm_.size()), mine));
  fluid::BadParticle out;
  for (const std::vector<std::byte>& b : all) {
    if (b.size() != mine.size() || b[0] == std::byte(0)) continue;
    fluid::BadParticle one;
    one.found = true;
    one.pastBound = b[1] != std::byte(0);
    one.quantity =
        kQuantities[std::min<std::size_t>(std::size_t(b[2]), std::size(kQuantities) - 1)];
    std::memcpy(&one.id, b.data() + 3, sizeof one.id);
    std::memcpy(&one.value, b.data() + 3 + sizeof one.id, sizeof one.value);
    if (!out.found || one.id < out.id) out = one;
  }
  return out;
}

DistributedStats FluidDecomposition::stats() const {
  DistributedStats out = stats_;
  const double n = double(stats_.exchanges);
  out.meanGhostShare = n > 0 ? ghostShareSum_ / n : 0.0;
  out.meanMigratedPerStep = n > 1 ? migratedSum_ / (n - 1) : 0.0;
  return out;
}

}  // namespace sph::distributed
