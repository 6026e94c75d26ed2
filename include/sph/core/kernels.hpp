// Smoothing kernels with support radius h (zero for r ≥ h). Each set provides what the passes
// need, under the same member names, so a pass is a template on the set and chooses it once:
//   W(r²)                  density and colour field
//   gradFactor(r)          ∇W(r) = gradFactor(r) · r⃗   (r⃗ = x_i - x_j), the pressure gradient
//   laplacian(r)           ∇²W(r) for the Müller viscosity
//   colourGradFactor(r)    ∇C of the colour field from W (surface normal, Meteer 2011, eq. 12)
//   colourLaplacian(r)     ∇²C of the same field (surface tension curvature)
// Coefficients are computed once on the host (`make`) and passed by value to the device.
#pragma once

#include "sph/core/constants.hpp"
#include "sph/core/select.hpp"
#include "sph/core/vec.hpp"

namespace sph {

// Müller et al. 2003 (the default of both Meteer 2011 and the 2021 CUDA SPH tutorial): poly6
// for W, spiky gradient for pressure, the viscosity kernel's Laplacian for viscosity.
template <class Real>
struct MullerKernels {
  Real h, h2;
  Real poly6;          // 315 / (64 π h⁹)
  Real spikyGradient;  // -45 / (π h⁶); Meteer 2011, eq. 8, writes the power as 3: a typo
  Real viscosityLap;   // 45 / (π h⁶), Meteer 2011, eq. 9

  static MullerKernels make(double h) {
    const double h3 = h * h * h, h6 = h3 * h3, h9 = h6 * h3;
    return {Real(h), Real(h * h), Real(315.0 / (64.0 * kPi * h9)), Real(-45.0 / (kPi * h6)),
            Real(45.0 / (kPi * h6))};
  }
  // W is generic over the argument (a float, or a SIMD batch: see select.hpp).
  template <class T = Real>
  SPH_HD T W(T r2) const {
    const T d = T(h2) - r2;
    return select(r2 < T(h2), T(poly6) * d * d * d, T(0));
  }
  // The factors below are generic over the argument too; zero outside the support.
  template <class T = Real>
  SPH_HD T gradFactor(T r) const {
    const T d = T(h) - r;
    const auto inside = r < T(h) && r > T(0);
    return select(inside, T(spikyGradient) * d * d / select(inside, r, T(1)), T(0));
  }
  // The kernels whose gradient and Laplacian the passes use, for checks and plots.
  SPH_HD Real spiky(Real r) const {
    const Real d = h - r;
    return r >= h ? Real(0) : -spikyGradient / Real(3) * d * d * d;  // 15 / (π h⁶) (h-r)³
  }
  SPH_HD Real viscosity(Real r) const {  // 15/(2π h³) (-r³/2h³ + r²/h² + h/2r - 1)
    if (r >= h) return Real(0);
    const Real q = r / h;
    return viscosityLap * h * h * h / Real(6) *
           (-q * q * q / Real(2) + q * q + Real(1) / (Real(2) * q) - Real(1));
  }
  template <class T = Real>
  SPH_HD T laplacian(T r) const {
    return select(r < T(h), T(viscosityLap) * (T(h) - r), T(0));
  }
  template <class T = Real>
  SPH_HD T colourGradFactor(T r) const {
    const T d = T(h2) - r * r;
    return select(r < T(h), T(-6) * T(poly6) * d * d, T(0));
  }
  template <class T = Real>
  SPH_HD T colourLaplacian(T r) const {
    const T r2 = r * r;
    return select(r < T(h), T(-6) * T(poly6) * (T(h2) - r2) * (T(3) * T(h2) - T(7) * r2), T(0));
  }
};

// Monaghan's cubic B-spline, rescaled to support h (q = r/h).
template <class Real>
struct CubicSplineKernels {
  Real h, h2, invH, sigma;  // σ = 8 / (π h³)

  static CubicSplineKernels make(double h) {
    return {Real(h), Real(h * h), Real(1.0 / h), Real(8.0 / (kPi * h * h * h))};
  }
  template <class T = Real>
  SPH_HD T W(T r2) const {
    const T q = realSqrt(r2) * T(invH);
    const T d = T(1) - q;
    const T w = select(q <= T(0.5f), T(sigma) * (T(6) * q * q * (q - T(1)) + T(1)),
                       T(sigma) * T(2) * d * d * d);
    return select(r2 < T(h2), w, T(0));
  }
  // dW/dr
  template <class T = Real>
  SPH_HD T derivative(T r) const {
    const T q = r * T(invH);
    const T d = T(1) - q;
    const T inner = T(sigma) * T(invH) * q * (T(18) * q - T(12));
    const T outer = T(-6) * T(sigma) * T(invH) * d * d;
    return select(q < T(1), select(q <= T(0.5f), inner, outer), T(0));
  }
  // W'(r)/r; zero at r = 0, where a particle meets itself.
  template <class T = Real>
  SPH_HD T gradFactor(T r) const {
    return select(r > T(0), derivative(r) / select(r > T(0), r, T(1)), T(0));
  }
  // Brookshaw's approximation -2 W'(r)/r: positive, so viscosity only dissipates.
  template <class T = Real>
  SPH_HD T laplacian(T r) const {
    const T q = r * T(invH);
    const T inner = T(-2) * T(sigma) * T(invH) * T(invH) * (T(18) * q - T(12));
    return select(q <= T(0.5f), select(q < T(1), inner, T(0)), T(-2) * gradFactor(r));
  }
  template <class T = Real>
  SPH_HD T colourGradFactor(T r) const {
    return gradFactor(r);
  }
  // W'' + 2 W'/r
  template <class T = Real>
  SPH_HD T colourLaplacian(T r) const {
    const T q = r * T(invH);
    const T c = T(sigma) * T(invH) * T(invH);
    const T inner = c * (T(72) * q - T(36));
    const T outer = c * (T(1) - q) * (T(12) - T(12) * (T(1) - q) / select(q > T(0), q, T(1)));
    return select(q < T(1), select(q <= T(0.5f), inner, outer), T(0));
  }
};

// Wendland C2 in 3-D (Wendland 1995; Dehnen & Aly 2012), support h.
template <class Real>
struct WendlandC2Kernels {
  Real h, h2, invH, sigma;  // σ = 21 / (2 π h³)

  static WendlandC2Kernels make(double h) {
    return {Real(h), Real(h * h), Real(1.0 / h), Real(21.0 / (2.0 * kPi * h * h * h))};
  }
  template <class T = Real>
  SPH_HD T W(T r2) const {
    const T q = realSqrt(r2) * T(invH);
    const T d = T(1) - q;
    const T d2 = d * d;
    return select(r2 < T(h2), T(sigma) * d2 * d2 * (T(1) + T(4) * q), T(0));
  }
  // dW/dr / r = -20 σ (1-q)³ / h²: finite at r = 0.
  template <class T = Real>
  SPH_HD T gradFactor(T r) const {
    const T q = r * T(invH);
    const T d = T(1) - q;
    return select(q < T(1), T(-20) * T(sigma) * T(invH) * T(invH) * d * d * d, T(0));
  }
  template <class T = Real>
  SPH_HD T laplacian(T r) const {
    return T(-2) * gradFactor(r);
  }
  template <class T = Real>
  SPH_HD T colourGradFactor(T r) const {
    return gradFactor(r);
  }
  // W'' + 2 W'/r = -20 σ (1-q)² (3 - 6q) / h²
  template <class T = Real>
  SPH_HD T colourLaplacian(T r) const {
    const T q = r * T(invH);
    const T d = T(1) - q;
    return select(q < T(1), T(-20) * T(sigma) * T(invH) * T(invH) * d * d * (T(3) - T(6) * q),
                  T(0));
  }
};

}  // namespace sph
