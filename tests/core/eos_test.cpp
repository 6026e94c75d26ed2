#include "sph/core/eos.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace sph {
namespace {

TEST(EquationOfState, LinearIsStiffnessTimesDensityExcess) {
  EXPECT_DOUBLE_EQ(pressureFromDensity(EquationOfState::Linear, 1010.0, 1000.0, 3.0, true), 30.0);
}

TEST(EquationOfState, RatioIsStiffnessTimesRelativeExcess) {
  EXPECT_NEAR(pressureFromDensity(EquationOfState::Ratio, 1010.0, 1000.0, 500.0, true), 5.0, 1e-12);
}

TEST(EquationOfState, TaitUsesSeventhPower) {
  const double p = pressureFromDensity(EquationOfState::Tait, 1010.0, 1000.0, 2.0, true);
  EXPECT_NEAR(p, 2.0 * (std::pow(1.01, 7) - 1.0), 1e-12);
}

TEST(EquationOfState, NegativePressureClampedUnlessAsked) {
  for (auto eos : {EquationOfState::Linear, EquationOfState::Ratio, EquationOfState::Tait}) {
    EXPECT_EQ(pressureFromDensity(eos, 990.0, 1000.0, 7.0, true), 0.0);
    EXPECT_LT(pressureFromDensity(eos, 990.0, 1000.0, 7.0, false), 0.0);
  }
}

TEST(EquationOfState, CompressionIgnoresADeficit) {
  EXPECT_NEAR(compression(1012.0, 1000.0), 0.012, 1e-12);
  EXPECT_EQ(compression(950.0, 1000.0), 0.0);
}

// dp/dρ at rest must be c0² for every form, so the derived stiffness gives the chosen sound speed.
TEST(EquationOfState, StiffnessGivesTheSoundSpeed) {
  const double c0 = 20.0, rho0 = 1000.0, e = 1e-3;
  for (auto eos : {EquationOfState::Linear, EquationOfState::Ratio, EquationOfState::Tait}) {
    const double k = stiffnessForSoundSpeed(eos, c0, rho0);
    const double dp = pressureFromDensity(eos, rho0 + e, rho0, k, false) -
                      pressureFromDensity(eos, rho0 - e, rho0, k, false);
    EXPECT_NEAR(dp / (2 * e), c0 * c0, 1e-3 * c0 * c0);
    EXPECT_NEAR(soundSpeedForStiffness(eos, k, rho0), c0, 1e-12 * c0);
  }
}

}  // namespace
}  // namespace sph
