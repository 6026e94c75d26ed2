// Stage: all forces in one pass (Meteer 2011, Algorithm 2): pressure (unless the incompressible
// solver gives it), viscosity, surface tension, gravity and external accelerations. Reads position,
// velocity, pressureState, the neighbour lists, the walls and externalById. Writes acceleration (w:
// 0; |∇c| for the surface flags is measured when a frame is taken, measure_surface.hpp). The colour
// field is summed only for surface tension, which needs it: it is a fifth of the pass.
#pragma once

#include <cstdint>
#include <type_traits>

#include "fluid/kernel_dispatch.hpp"
#include "fluid/neighbor_walk.hpp"
#include "fluid/pair_terms.hpp"
#include "fluid/particles.hpp"

namespace sph::fluid {

// What the force pass reads of a neighbour, 8 floats, so that 8 neighbours load as 8 rows and
// transpose into batches.
struct ForceRecord {
  enum Field { kX, kY, kZ, kPressureTerm, kVX, kVY, kVZ, kDensity };
};

// Particle i's acceleration: ForceTerms (pair_terms.hpp) over its neighbours, walls and objects'
// particles (neighbor_walk.hpp), with gravity, the external acceleration and surface tension.
template <class Options, class Kernels>
struct ForcePass {
  static constexpr bool kGradients = false;  // pressure, viscosity and colour read the pair
  static constexpr bool kSkipsCoincident = false;
  static constexpr bool kWalls = true;
  static constexpr bool kObjects = true;
  static constexpr std::uint32_t kColumns = 8;
  // The parameters every pair reads, made once a pass for each width.
  ForceConstants<float, Vec3, Kernels> constants;
#if !defined(__CUDACC__)
  ForceConstants<FloatBatch, BatchVec3, Kernels> batchConstants;
#endif
  const Vec4* state;
  const Vec4* velocity;
  const std::uint32_t* id;
  const Vec4* external;  // by id; null: none
  Vec4* acceleration;

  template <class S, class V>
  SPH_HD_INLINE const ForceConstants<S, V, Kernels>& constantsFor() const {
#if !defined(__CUDACC__)
    if constexpr (std::is_same_v<S, FloatBatch>) return batchConstants;
#endif
    if constexpr (std::is_same_v<S, float>) return constants;
  }
  // Particle i's state, and what it sums. Its terms (ForceTerms) are made again for each pair
  // from these plain values, which the compiler keeps in registers through the walk.
  template <class S, class V>
  struct Sum {
    PressureState state;
    Vec3 velocity;
    ForceSums<S, V> sums;
  };
  template <class S, class V>
  SPH_HD_INLINE ForceTerms<S, V, Options, Kernels> terms(const Sum<S, V>& sum) const {
    return ForceTerms<S, V, Options, Kernels>(constantsFor<S, V>(), sum.state, sum.velocity);
  }
  template <class S, class V>
  SPH_HD_INLINE Sum<S, V> start(std::size_t i) const {
    return {unpackPressureState(state[i]), xyz(velocity[i]), ForceSums<S, V>{}};
  }
  template <class S, class V, class M, class C>
  SPH_HD_INLINE void addFluid(Sum<S, V>& sum, const Pair<S, V, M>& pair, const C& columns) const {
    using R = ForceRecord;
    terms(sum).addFluid(sum.sums, pair, V{columns[R::kVX], columns[R::kVY], columns[R::kVZ]},
                        columns[R::kPressureTerm], columns[R::kDensity]);
  }
  template <class S, class V, class M>
  SPH_HD_INLINE void addWall(Sum<S, V>& sum, const Pair<S, V, M>& pair, S volume) const {
    terms(sum).addWall(sum.sums, pair, volume);
  }
  template <class S, class V, class M>
  SPH_HD_INLINE void addMovingWall(Sum<S, V>& sum, const Pair<S, V, M>& pair, S volume,
                                   const V& velocityB) const {
    terms(sum).addObject(sum.sums, pair, volume, velocityB);
  }
  template <class S, class V>
  SPH_HD_INLINE void finish(std::size_t i, const Sum<S, V>& sum) const {
    const Vec3 extra = external ? xyz(external[id[i]]) : Vec3{0.0f, 0.0f, 0.0f};
    acceleration[i] = makeVec4(terms(sum).total(sum.sums, extra), 0.0f);
  }
};

namespace detail {

// The force records of the particles as they are now, and of the padding: far away, with no
// pressure or velocity and a density of 1 to divide by.
template <class B, class Options>
void writeForceRecords(FluidParticles<B>& fluid) {
  using R = ForceRecord;
  const std::size_t n = fluid.count;
  fluid.batchRecords.resize(kRecordFields * (n + kBatchPadding));
  float* records = fluid.batchRecords.data();
  const Vec4* position = fluid.position.data();
  const Vec4* velocity = fluid.velocity.data();
  const Vec4* state = fluid.pressureState.data();
  B::forEach(
      n + kBatchPadding, SPH_LAMBDA(std::size_t i) {
        float* r = records + kRecordFields * i;
        if (i >= n) {
          r[R::kX] = r[R::kY] = r[R::kZ] = 1e30f;
          r[R::kPressureTerm] = r[R::kVX] = r[R::kVY] = r[R::kVZ] = 0.0f;
          r[R::kDensity] = 1.0f;
          return;
        }
        const Vec4 x = position[i], v = velocity[i];
        const PressureState s = unpackPressureState(state[i]);
        r[R::kX] = x.x;
        r[R::kY] = x.y;
        r[R::kZ] = x.z;
        r[R::kPressureTerm] = pressureTerm<Options>(s);
        r[R::kVX] = v.x;
        r[R::kVY] = v.y;
        r[R::kVZ] = v.z;
        r[R::kDensity] = s.density;
      });
}

template <class B, class Options>
void forcePassWithKernels(FluidParticles<B>& fluid, const Grid<B>& grid,
                          const BoundaryParticles<B>& boundary, const BoundaryParticles<B>& objects,
                          const FluidParameters& params, NeighborWalk walk) {
  writeForceRecords<B, Options>(fluid);
  withKernels(params, [&](auto kernels) {
    using Kernels = decltype(kernels);
    const ForcePass<Options, Kernels> pass {
      ForceConstants<float, Vec3, Kernels>(params, kernels),
#if !defined(__CUDACC__)
          ForceConstants<FloatBatch, BatchVec3, Kernels>(params, kernels),
#endif
          fluid.pressureState.data(), fluid.velocity.data(), fluid.id.data(),
          fluid.externalById.size() ? fluid.externalById.data() : nullptr, fluid.acceleration.data()
    };
    runPass(fluid, grid, boundary, objects, fluid.batchRecords.data(), kernels, params.periodic,
            walk, pass);
  });
}

template <class B, PressureForm kForm, ViscosityModel kViscosity, bool kPressure>
void forcePassWithTension(FluidParticles<B>& fluid, const Grid<B>& grid,
                          const BoundaryParticles<B>& boundary, const BoundaryParticles<B>& objects,
                          const FluidParameters& params, NeighborWalk walk) {
  if (params.surfaceTension > 0.0f) {
    forcePassWithKernels<B, ForceOptions<kForm, kViscosity, true, kPressure>>(
        fluid, grid, boundary, objects, params, walk);
  } else {
    forcePassWithKernels<B, ForceOptions<kForm, kViscosity, false, kPressure>>(
        fluid, grid, boundary, objects, params, walk);
  }
}

template <class B, PressureForm kForm, bool kPressure = true>
void forcePassWithViscosity(FluidParticles<B>& fluid, const Grid<B>& grid,
                            const BoundaryParticles<B>& boundary,
                            const BoundaryParticles<B>& objects, const FluidParameters& params,
                            NeighborWalk walk) {
  if (params.viscosityModel == ViscosityModel::Artificial) {
    forcePassWithTension<B, kForm, ViscosityModel::Artificial, kPressure>(fluid, grid, boundary,
                                                                          objects, params, walk);
  } else {
    forcePassWithTension<B, kForm, ViscosityModel::Muller, kPressure>(fluid, grid, boundary,
                                                                      objects, params, walk);
  }
}

}  // namespace detail

// objects: the objects' particles as boundary particles (interaction.coupling "boundary"), or
// none.
template <class B>
void computeForces(FluidParticles<B>& fluid, const Grid<B>& grid,
                   const BoundaryParticles<B>& boundary, const BoundaryParticles<B>& objects,
                   const FluidParameters& params, NeighborWalk walk) {
  if (!params.pressureForces) {
    detail::forcePassWithViscosity<B, PressureForm::Symmetric, false>(fluid, grid, boundary,
                                                                      objects, params, walk);
  } else if (params.pressureForm == PressureForm::Symmetric) {
    detail::forcePassWithViscosity<B, PressureForm::Symmetric>(fluid, grid, boundary, objects,
                                                               params, walk);
  } else {
    detail::forcePassWithViscosity<B, PressureForm::Paper>(fluid, grid, boundary, objects, params,
                                                           walk);
  }
}

}  // namespace sph::fluid
