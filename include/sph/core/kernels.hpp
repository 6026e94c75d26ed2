// Smoothing kernels with support radius h (zero for r ≥ h). Each set provides what the passes
// need, under the same member names, so a pass is a template on the set and chooses it once:
//   W(r²)                  density and colour field
//   gradFactor(r)          ∇W(r) = gradFactor(r) · r⃗   (r⃗ = x_i - x_j), the pressure gradient
//   laplacian(r)           ∇²W(r) for the Müller viscosity
//   colourGradFactor(r)    ∇C of the colour field built from W (surface normal, seed 1 eq. 12)
//   colourLaplacian(r)     ∇²C of the same field (surface tension curvature)
// Coefficients are computed once on the host (`make`) and passed by value to the device.
#pragma once

#include "sph/core/vec.hpp"

namespace sph {

constexpr double kPi = 3.14159265358979323846;

// Müller et al. 2003 (the seeds' default): poly6 for W, spiky gradient for pressure,
// the viscosity kernel's Laplacian for viscosity.
template <class Real>
struct MullerKernels {
  Real h, h2;
  Real poly6;          // 315 / (64 π h⁹)
  Real spikyGradient;  // -45 / (π h⁶); seed 1 eq. 8 writes the power as 3: a typo
  Real viscosityLap;   // 45 / (π h⁶), seed 1 eq. 9

  static MullerKernels make(double h) {
    const double h3 = h * h * h, h6 = h3 * h3, h9 = h6 * h3;
    return {Real(h), Real(h * h), Real(315.0 / (64.0 * kPi * h9)), Real(-45.0 / (kPi * h6)),
            Real(45.0 / (kPi * h6))};
  }
  SPH_HD Real W(Real r2) const {
    if (r2 >= h2) return Real(0);
    const Real d = h2 - r2;
    return poly6 * d * d * d;
  }
  SPH_HD Real gradFactor(Real r) const {
    if (r >= h || r <= Real(0)) return Real(0);
    const Real d = h - r;
    return spikyGradient * d * d / r;
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
  SPH_HD Real laplacian(Real r) const { return r >= h ? Real(0) : viscosityLap * (h - r); }
  SPH_HD Real colourGradFactor(Real r) const {
    const Real d = h2 - r * r;
    return r >= h ? Real(0) : Real(-6) * poly6 * d * d;
  }
  SPH_HD Real colourLaplacian(Real r) const {
    const Real r2 = r * r;
    return r >= h ? Real(0) : Real(-6) * poly6 * (h2 - r2) * (Real(3) * h2 - Real(7) * r2);
  }
};

// Monaghan's cubic B-spline, rescaled to support h (q = r/h).
template <class Real>
struct CubicSplineKernels {
  Real h, h2, invH, sigma;  // σ = 8 / (π h³)

  static CubicSplineKernels make(double h) {
    return {Real(h), Real(h * h), Real(1.0 / h), Real(8.0 / (kPi * h * h * h))};
  }
  SPH_HD Real W(Real r2) const {
    if (r2 >= h2) return Real(0);
    const Real q = realSqrt(r2) * invH;
    if (q <= Real(0.5)) return sigma * (Real(6) * q * q * (q - Real(1)) + Real(1));
    const Real d = Real(1) - q;
    return sigma * Real(2) * d * d * d;
  }
  // dW/dr
  SPH_HD Real derivative(Real r) const {
    const Real q = r * invH;
    if (q >= Real(1)) return Real(0);
    if (q <= Real(0.5)) return sigma * invH * q * (Real(18) * q - Real(12));
    const Real d = Real(1) - q;
    return Real(-6) * sigma * invH * d * d;
  }
  SPH_HD Real gradFactor(Real r) const { return r <= Real(0) ? Real(0) : derivative(r) / r; }
  // Brookshaw's approximation -2 W'(r)/r: positive, so viscosity only dissipates.
  SPH_HD Real laplacian(Real r) const {
    const Real q = r * invH;
    if (q >= Real(1)) return Real(0);
    if (q <= Real(0.5)) return Real(-2) * sigma * invH * invH * (Real(18) * q - Real(12));
    return r <= Real(0) ? Real(0) : Real(-2) * derivative(r) / r;
  }
  SPH_HD Real colourGradFactor(Real r) const { return gradFactor(r); }
  // W'' + 2 W'/r
  SPH_HD Real colourLaplacian(Real r) const {
    const Real q = r * invH;
    if (q >= Real(1)) return Real(0);
    if (q <= Real(0.5)) return sigma * invH * invH * (Real(72) * q - Real(36));
    return sigma * invH * invH * (Real(1) - q) * (Real(12) - Real(12) * (Real(1) - q) / q);
  }
};

// Wendland C2 in 3-D (Wendland 1995; Dehnen & Aly 2012), support h.
template <class Real>
struct WendlandC2Kernels {
  Real h, h2, invH, sigma;  // σ = 21 / (2 π h³)

  static WendlandC2Kernels make(double h) {
    return {Real(h), Real(h * h), Real(1.0 / h), Real(21.0 / (2.0 * kPi * h * h * h))};
  }
  SPH_HD Real W(Real r2) const {
    if (r2 >= h2) return Real(0);
    const Real q = realSqrt(r2) * invH;
    const Real d = Real(1) - q;
    const Real d2 = d * d;
    return sigma * d2 * d2 * (Real(1) + Real(4) * q);
  }
  // dW/dr / r = -20 σ (1-q)³ / h²: finite at r = 0.
  SPH_HD Real gradFactor(Real r) const {
    const Real q = r * invH;
    if (q >= Real(1)) return Real(0);
    const Real d = Real(1) - q;
    return Real(-20) * sigma * invH * invH * d * d * d;
  }
  SPH_HD Real laplacian(Real r) const { return Real(-2) * gradFactor(r); }
  SPH_HD Real colourGradFactor(Real r) const { return gradFactor(r); }
  // W'' + 2 W'/r = -20 σ (1-q)² (3 - 6q) / h²
  SPH_HD Real colourLaplacian(Real r) const {
    const Real q = r * invH;
    if (q >= Real(1)) return Real(0);
    const Real d = Real(1) - q;
    return Real(-20) * sigma * invH * invH * d * d * (Real(3) - Real(6) * q);
  }
};

}  // namespace sph
