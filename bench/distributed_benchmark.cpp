// What a distributed step moves between ranks, and how long that takes: a block of fluid on a
// lattice (64³ = 262,144 particles by default, the size the efficiency figure names)
// partitioned by RCB over the ranks, then for each of `--steps` steps its particles moved a
// little (up to a tenth of the spacing, in a shearing flow), re-assigned, migrated, their halo planned for a
// support radius of twice the spacing and sent with eight values a particle (position,
// velocity, density, pressure), and one field refreshed (density and pressure, two values).
// Rank 0 prints one JSON line: the particles each rank owns and receives as halo, those
// migrated a step, and the median seconds of each part (the slowest rank's), with the
// imbalance of the partition.
//
//   mpirun -np 2 build/bench/sph_distributed_benchmark [--side 64] [--steps 20]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "distributed/communicator.hpp"
#include "distributed/particle_exchange.hpp"
#include "distributed/partition.hpp"

namespace {

using sph::distributed::Communicator;
using sph::distributed::ParticleRecords;

constexpr float kSpacing = 0.01f;
constexpr int kWidth = 8;

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// Each rank's share of the lattice to start with: every size-th id.
ParticleRecords startingShare(const Communicator& comm, int side) {
  ParticleRecords r;
  r.width = kWidth;
  const auto n = std::uint32_t(side) * std::uint32_t(side) * std::uint32_t(side);
  for (std::uint32_t id = std::uint32_t(comm.rank()); id < n; id += std::uint32_t(comm.size())) {
    r.id.push_back(id);
    const float x = kSpacing * float(id % std::uint32_t(side));
    const float y = kSpacing * float((id / std::uint32_t(side)) % std::uint32_t(side));
    const float z = kSpacing * float(id / (std::uint32_t(side) * std::uint32_t(side)));
    r.value.insert(r.value.end(), {x, y, z, 0.0f, 0.0f, 0.0f, 1000.0f, 0.0f});
  }
  return r;
}

// A shearing flow that crosses every axis-aligned plane: each axis moves with the next one's
// position, a tenth of the spacing a step at the block's faces.
void move(ParticleRecords& r, int side) {
  const float extent = kSpacing * float(side - 1);
  for (std::size_t i = 0; i < r.size(); ++i) {
    float* p = r.value.data() + i * kWidth;
    const float s[3] = {p[1] / extent - 0.5f, p[2] / extent - 0.5f, p[0] / extent - 0.5f};
    for (int c = 0; c < 3; ++c) p[c] += 0.2f * kSpacing * s[c];
  }
}

std::vector<float> positions(const ParticleRecords& r) {
  std::vector<float> p;
  p.reserve(3 * r.size());
  for (std::size_t i = 0; i < r.size(); ++i) p.insert(p.end(), r.of(i), r.of(i) + 3);
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  sph::distributed::MpiSession mpi(argc, argv);
  const Communicator comm;
  int side = 64, steps = 20;
  for (int a = 1; a + 1 < argc; a += 2) {
    if (std::strcmp(argv[a], "--side") == 0) side = std::max(4, std::atoi(argv[a + 1]));
    if (std::strcmp(argv[a], "--steps") == 0) steps = std::max(1, std::atoi(argv[a + 1]));
  }
  sph::distributed::GeometricPartitioner partitioner(comm, sph::distributed::PartitionMethod::Rcb);
  ParticleRecords owned = startingShare(comm, side);
  owned = sph::distributed::migrate(comm, owned, partitioner.assign(positions(owned), {}));

  std::vector<double> assignTime, migrateTime, planTime, haloTime, refreshTime, migrated, halo;
  for (int step = 0; step < steps; ++step) {
    move(owned, side);
    comm.barrier();
    double t = now();
    const std::vector<int> owner = partitioner.assign(positions(owned), {});
    assignTime.push_back(comm.max(now() - t));
    std::uint64_t leaving = 0;
    for (int r : owner) leaving += r != comm.rank();
    migrated.push_back(double(comm.sum(leaving)));
    t = now();
    owned = sph::distributed::migrate(comm, owned, owner);
    migrateTime.push_back(comm.max(now() - t));
    t = now();
    const sph::distributed::HaloPlan plan =
        sph::distributed::planHalo(comm, owned, 2.0f * kSpacing);
    planTime.push_back(comm.max(now() - t));
    t = now();
    const ParticleRecords ghosts = sph::distributed::exchangeHalo(comm, plan, owned);
    haloTime.push_back(comm.max(now() - t));
    halo.push_back(double(comm.sum(std::uint64_t(ghosts.size()))));
    ParticleRecords field;
    field.width = 2;
    field.id = owned.id;
    field.value.resize(2 * owned.size(), 1000.0f);
    t = now();
    sph::distributed::exchangeHalo(comm, plan, field);
    refreshTime.push_back(comm.max(now() - t));
  }
  const double total = double(side) * side * side;
  const double imbalance = sph::distributed::imbalance(comm, double(owned.size()));
  if (comm.rank() == 0)
    std::printf(
        "{\"ranks\": %d, \"particles\": %.0f, \"steps\": %d, \"owned_per_rank\": %.0f, "
        "\"halo_per_rank\": %.0f, \"halo_fraction\": %.4f, \"migrated_per_step\": %.0f, "
        "\"imbalance\": %.4f, \"assign_s\": %.6f, \"migrate_s\": %.6f, \"plan_s\": %.6f, "
        "\"halo_s\": %.6f, \"refresh_s\": %.6f}\n",
        comm.size(), total, steps, total / comm.size(), median(halo) / comm.size(),
        median(halo) / total, median(migrated), imbalance, median(assignTime), median(migrateTime),
        median(planTime), median(haloTime), median(refreshTime));
  return 0;
}
