// Equations of state (the 2021 CUDA SPH tutorial) and the stiffness that gives a chosen
// speed of sound.
#pragma once

#include <cmath>

#include "sph/core/hostdevice.hpp"
#include "sph/core/options.hpp"

namespace sph {

// Pressure from density. Clamping negative pressure keeps the free surface from tearing
// apart (particles there lack neighbours, so their density reads low).
template <class Real>
SPH_HD Real pressureFromDensity(EquationOfState eos, Real density, Real restDensity, Real stiffness,
                                bool clampNegative) {
  Real p;
  switch (eos) {
    case EquationOfState::Linear:  // Meteer 2011, eq. 5 with p0 = 0
      p = stiffness * (density - restDensity);
      break;
    case EquationOfState::Ratio:
      p = stiffness * (density / restDensity - Real(1));
      break;
    default: {  // Tait, exponent 7
      const Real x = density / restDensity;
      const Real x2 = x * x;
      p = stiffness * (x2 * x2 * x2 * x - Real(1));
    }
  }
  return (clampNegative && p < Real(0)) ? Real(0) : p;
}

// The density error the failure bound and the statistics use: compression ρ/ρ0 - 1, or 0. A
// free surface's particles lack neighbours and read low, which is not an error of the method.
template <class Real>
SPH_HD Real compression(Real density, Real restDensity) {
  const Real e = density / restDensity - Real(1);
  return e > Real(0) ? e : Real(0);
}

// The stiffness for which dp/dρ at rest equals c0², i.e. the sound speed is c0.
inline double stiffnessForSoundSpeed(EquationOfState eos, double soundSpeed, double restDensity) {
  const double c2 = soundSpeed * soundSpeed;
  switch (eos) {
    case EquationOfState::Linear:
      return c2;  // k = c0²
    case EquationOfState::Ratio:
      return restDensity * c2;  // k = ρ0 c0²
    default:
      return restDensity * c2 / 7.0;  // B = ρ0 c0² / 7
  }
}

// The inverse: the sound speed a stiffness gives.
inline double soundSpeedForStiffness(EquationOfState eos, double stiffness, double restDensity) {
  return std::sqrt(stiffness / stiffnessForSoundSpeed(eos, 1.0, restDensity));
}

}  // namespace sph
