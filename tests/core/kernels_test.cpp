#include "sph/core/kernels.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace sph {
namespace {

constexpr double kH = 0.02;

// ∫ 4π r² f(r) dr over [r0, h] by composite Simpson.
double integrateOverBall(const std::function<double(double)>& f, double r0 = 0.0) {
  const int n = 20000;
  const double step = (kH - r0) / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double r = r0 + i * step;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += w * 4.0 * kPi * r * r * f(r);
  }
  return sum * step / 3.0;
}

double derivative(const std::function<double(double)>& f, double r) {
  const double e = 1e-7;
  return (f(r + e) - f(r - e)) / (2.0 * e);
}

double laplacianOfRadial(const std::function<double(double)>& f, double r) {
  const double e = 1e-5;
  const double second = (f(r + e) - 2.0 * f(r) + f(r - e)) / (e * e);
  return second + 2.0 / r * derivative(f, r);
}

template <class K>
std::function<double(double)> radialW(const K& k) {
  return [k](double r) { return k.W(r * r); };
}

TEST(Kernels, Poly6IntegratesToOne) {
  EXPECT_NEAR(integrateOverBall(radialW(MullerKernels<double>::make(kH))), 1.0, 1e-3);
}

TEST(Kernels, SpikyIntegratesToOne) {
  auto k = MullerKernels<double>::make(kH);
  EXPECT_NEAR(integrateOverBall([&](double r) { return k.spiky(r); }), 1.0, 1e-3);
}

TEST(Kernels, ViscosityKernelIntegratesToOne) {
  auto k = MullerKernels<double>::make(kH);
  // Singular like 1/r at the origin, integrable: start just off it.
  EXPECT_NEAR(integrateOverBall([&](double r) { return k.viscosity(r); }, 1e-9), 1.0, 1e-3);
}

TEST(Kernels, CubicSplineIntegratesToOne) {
  EXPECT_NEAR(integrateOverBall(radialW(CubicSplineKernels<double>::make(kH))), 1.0, 1e-3);
}

TEST(Kernels, WendlandC2IntegratesToOne) {
  EXPECT_NEAR(integrateOverBall(radialW(WendlandC2Kernels<double>::make(kH))), 1.0, 1e-3);
}

TEST(Kernels, SpikyGradientMatchesFiniteDifference) {
  auto k = MullerKernels<double>::make(kH);
  for (double q : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    const double r = q * kH;
    const double fd = derivative([&](double x) { return k.spiky(x); }, r);
    EXPECT_NEAR(k.gradFactor(r) * r, fd, 1e-6 * std::abs(fd) + 1e-3) << "q=" << q;
  }
}

TEST(Kernels, ViscosityLaplacianMatchesFiniteDifference) {
  auto k = MullerKernels<double>::make(kH);
  for (double q : {0.2, 0.4, 0.6, 0.8}) {
    const double r = q * kH;
    const double fd = laplacianOfRadial([&](double x) { return k.viscosity(x); }, r);
    EXPECT_NEAR(k.laplacian(r), fd, 1e-3 * std::abs(fd)) << "q=" << q;
  }
}

template <class K>
void expectGradientsMatch(const K& k) {
  auto w = radialW(k);
  for (double q : {0.05, 0.2, 0.45, 0.55, 0.8, 0.95}) {
    const double r = q * kH;
    const double fd = derivative(w, r);
    EXPECT_NEAR(k.gradFactor(r) * r, fd, 1e-5 * std::abs(fd) + 1e-2) << "q=" << q;
    EXPECT_NEAR(k.colourGradFactor(r) * r, fd, 1e-5 * std::abs(fd) + 1e-2) << "q=" << q;
    const double lap = laplacianOfRadial(w, r);
    EXPECT_NEAR(k.colourLaplacian(r), lap, 1e-4 * std::abs(lap) + 1.0) << "q=" << q;
  }
}

TEST(Kernels, CubicSplineGradientsMatchFiniteDifference) {
  expectGradientsMatch(CubicSplineKernels<double>::make(kH));
}

TEST(Kernels, WendlandC2GradientsMatchFiniteDifference) {
  expectGradientsMatch(WendlandC2Kernels<double>::make(kH));
}

TEST(Kernels, Poly6ColourGradientsMatchFiniteDifference) {
  auto k = MullerKernels<double>::make(kH);
  auto w = radialW(k);
  for (double q : {0.1, 0.4, 0.7, 0.95}) {
    const double r = q * kH;
    const double fd = derivative(w, r);
    EXPECT_NEAR(k.colourGradFactor(r) * r, fd, 1e-5 * std::abs(fd) + 1e-2);
    const double lap = laplacianOfRadial(w, r);
    EXPECT_NEAR(k.colourLaplacian(r), lap, 1e-4 * std::abs(lap) + 1.0);
  }
}

// Brookshaw's Laplacian stands in for ∇²W in viscosity: it must be positive inside.
TEST(Kernels, ViscosityLaplaciansArePositiveInside) {
  auto c = CubicSplineKernels<double>::make(kH);
  auto w = WendlandC2Kernels<double>::make(kH);
  auto m = MullerKernels<double>::make(kH);
  for (double q = 0.01; q < 1.0; q += 0.01) {
    EXPECT_GT(c.laplacian(q * kH), 0.0);
    EXPECT_GT(w.laplacian(q * kH), 0.0);
    EXPECT_GT(m.laplacian(q * kH), 0.0);
  }
}

template <class K>
void expectVanishesOutside(const K& k) {
  for (double q : {1.0, 1.0001, 1.5, 3.0}) {
    const double r = q * kH;
    EXPECT_EQ(k.W(r * r), 0.0);
    EXPECT_EQ(k.gradFactor(r), 0.0);
    EXPECT_EQ(k.laplacian(r), 0.0);
    EXPECT_EQ(k.colourGradFactor(r), 0.0);
    EXPECT_EQ(k.colourLaplacian(r), 0.0);
  }
}

TEST(Kernels, VanishOutsideSupport) {
  expectVanishesOutside(MullerKernels<double>::make(kH));
  expectVanishesOutside(CubicSplineKernels<double>::make(kH));
  expectVanishesOutside(WendlandC2Kernels<double>::make(kH));
  auto m = MullerKernels<double>::make(kH);
  EXPECT_EQ(m.spiky(kH * 1.01), 0.0);
  EXPECT_EQ(m.viscosity(kH * 1.01), 0.0);
}

TEST(Kernels, FloatMatchesDouble) {
  auto d = MullerKernels<double>::make(kH);
  auto f = MullerKernels<float>::make(kH);
  const double r = 0.37 * kH;
  EXPECT_NEAR(f.W(float(r * r)), d.W(r * r), 1e-5 * d.W(r * r));
  EXPECT_NEAR(f.gradFactor(float(r)), d.gradFactor(r), 1e-5 * std::abs(d.gradFactor(r)));
}

}  // namespace
}  // namespace sph
