// The coarse level of the density solve (dfsph_solve.hpp). Jacobi carries a correction about a
// neighbourhood a pass, so the smooth part of the density error (a deep column's load) takes it
// many passes. Here that part is solved for at once on cells of a coarse grid: the bulk
// particles' errors are averaged into the cells, the continuum form of the solve,
//   Δt² ρ0 ∇²K = -e  (Δv = -Δt ρ0 ∇K and Δe = -Δt ∇·Δv, core/dfsph.hpp),
// is solved by conjugate gradients on the cells (K = 0 in the cells at the free surface, no flux
// into the walls'), and K is interpolated back to the particles. Host code: the solve is small
// (a cell holds about 64 particles) and serial, the interpolation parallel, and both the same on
// any thread count.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "sph/core/grid.hpp"
#include "sph/core/vec.hpp"

namespace sph::fluid {

// What the coarse level reads, host arrays.
struct CoarseInput {
  GridSpec fineGrid;  // the fluid's grid: the coarse cells are kCoarseCellsPerSide of its cells
  const Vec4* position = nullptr;  // fluid particles
  const float* density = nullptr;
  const float* error = nullptr;  // signed relative density error e_i the step would end with
  std::size_t count = 0;
  const Vec4* wall = nullptr;  // static boundary particles, w: volume ψ_b
  std::size_t wallCount = 0;
  float particleVolume = 0.0f;  // m/ρ0
  float restDensity = 0.0f;
  float dt = 0.0f;
};

// Side of a coarse cell in fine cells (h): 2h holds about 64 particles at h = 2d. Cells of h
// (8 particles) read the error too noisily: the front test's first point moved 2 % further off.
constexpr int kCoarseCellsPerSide = 2;

class CoarsePressure {
 public:
  enum Kind : std::uint8_t { kSurface, kFluid, kWall };

  // K for each particle (k, count of them), ≥ 0, to be added to Jacobi's. Returns false, k
  // untouched, where there is nothing to solve: no cell of bulk fluid that reaches the free
  // surface (fluid closed in on every side has its pressure fixed only up to a constant).
  bool solve(const CoarseInput& in, float* k);

 private:
  std::size_t index(Int3 c) const { return (std::size_t(c.z) * dims_.y + c.y) * dims_.x + c.x; }
  bool inside(Int3 c) const {
    return c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x < dims_.x && c.y < dims_.y && c.z < dims_.z;
  }
  Int3 coordinate(std::size_t k) const {
    return Int3{int(k % std::size_t(dims_.x)), int(k / std::size_t(dims_.x) % std::size_t(dims_.y)),
                int(k / (std::size_t(dims_.x) * std::size_t(dims_.y)))};
  }
  Int3 cellOf(Vec3 p) const;
  void keepCellsThatReachTheSurface();
  void bin(const CoarseInput& in);
  void classify();
  bool assemble(const CoarseInput& in);
  void conjugateGradients();
  void multiply(const std::vector<double>& in, std::vector<double>& out) const;
  float interpolate(Vec3 p) const;

  Vec3 origin_{};
  float size_ = 0.0f;
  Int3 dims_{};
  std::vector<double> errorSum_, occupancy_, cellK_;
  std::vector<std::uint32_t> bulkCount_, wallCount_;
  std::vector<std::uint8_t> kind_;
  std::vector<std::int32_t> row_;         // cell → unknown, or -1
  std::vector<std::uint32_t> cellOfRow_;  // unknown → cell
  std::vector<double> diagonal_, rhs_, x_, r_, z_, p_, q_;
};

}  // namespace sph::fluid
