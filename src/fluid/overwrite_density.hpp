// Stage of a distributed run: the ghosts' density as their owners computed it (a ghost near
// the edge of the halo misses neighbours, so its own sums read low), and the pressure and
// pressureState that follow from it, as the density pass would write them.
#pragma once

#include <cstdint>
#include <vector>

#include "fluid/pair_terms.hpp"
#include "fluid/particles.hpp"

namespace sph::fluid {

// rows[k] takes density[k].
template <class B>
void overwriteDensity(FluidParticles<B>& fluid, const std::vector<std::uint32_t>& rows,
                      const std::vector<float>& values, const FluidParameters& params,
                      typename B::template Buffer<std::uint32_t>& rowScratch,
                      typename B::template Buffer<float>& valueScratch) {
  const std::size_t n = rows.size();
  if (n == 0) return;
  B::upload(rowScratch, rows.data(), n);
  B::upload(valueScratch, values.data(), n);
  const std::uint32_t* row = rowScratch.data();
  const float* value = valueScratch.data();
  float* density = fluid.density.data();
  float* pressure = fluid.pressure.data();
  Vec4* state = fluid.pressureState.data();
  const FluidParameters p = params;
  B::forEach(
      n, SPH_LAMBDA(std::size_t k) {
        const PressureState s = pressureStateFromDensity(value[k], p);
        density[row[k]] = s.density;
        pressure[row[k]] = s.pressure;
        state[row[k]] = packed(s);
      });
}

}  // namespace sph::fluid
