// The incompressible solver's record (src/sim/solver_record.hpp): statistics and the failure
// report read its totals, so every solve's iterations add up and every solve that missed its
// tolerance counts. A divergence solve the scene left out still makes one pass, which has
// nothing to converge to and must not be reported as a failure.
#include "sim/solver_record.hpp"

#include <gtest/gtest.h>

namespace sph {
namespace {

fluid::SolverReport report(int iterations, bool converged, float averageError = 0.0f) {
  fluid::SolverReport r;
  r.iterations = iterations;
  r.converged = converged;
  r.averageError = averageError;
  return r;
}

TEST(SolverRecord, IterationsAddUpForEachSolveApart) {
  sim::SolverRecord record;
  record.addDensity(report(3, true));
  record.addDivergence(report(2, true), true);
  record.addDensity(report(5, true, 0.25f));
  record.addDivergence(report(7, true, 0.5f), true);
  EXPECT_EQ(record.densityIterations, 8u);
  EXPECT_EQ(record.divergenceIterations, 9u);
  EXPECT_EQ(record.unconvergedSolves, 0u);
  // The last of each is kept.
  EXPECT_EQ(record.density.iterations, 5);
  EXPECT_EQ(record.density.averageError, 0.25f);
  EXPECT_EQ(record.divergence.iterations, 7);
  EXPECT_EQ(record.divergence.averageError, 0.5f);
}

TEST(SolverRecord, EveryUnconvergedSolveCounts) {
  sim::SolverRecord record;
  record.addDensity(report(100, false));
  EXPECT_EQ(record.unconvergedSolves, 1u);
  EXPECT_FALSE(record.density.converged);
  record.addDivergence(report(100, false), true);
  EXPECT_EQ(record.unconvergedSolves, 2u);
  EXPECT_FALSE(record.divergence.converged);
  record.addDensity(report(4, true));
  EXPECT_EQ(record.unconvergedSolves, 2u);
  EXPECT_TRUE(record.density.converged);
  record.addDensity(report(100, false));
  EXPECT_EQ(record.unconvergedSolves, 3u);
  EXPECT_EQ(record.densityIterations, 204u);
}

TEST(SolverRecord, ADivergenceSolveTheSceneLeftOutCountsAsConverged) {
  sim::SolverRecord record;
  record.addDivergence(report(1, false), false);
  EXPECT_TRUE(record.divergence.converged);
  EXPECT_EQ(record.unconvergedSolves, 0u);
  EXPECT_EQ(record.divergenceIterations, 1u);  // its pass still counts as work
  // The same report from a solve the scene asked for is a failure.
  record.addDivergence(report(1, false), true);
  EXPECT_FALSE(record.divergence.converged);
  EXPECT_EQ(record.unconvergedSolves, 1u);
  EXPECT_EQ(record.divergenceIterations, 2u);
}

}  // namespace
}  // namespace sph
