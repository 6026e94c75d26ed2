// Chooses the kernel set once per pass; the pass body is a template on it, so the choice
// costs nothing per pair and needs no virtual call.
#pragma once

#include "fluid/parameters.hpp"
#include "sph/core/kernels.hpp"

namespace sph::fluid {

template <class Pass>
void withKernels(const FluidParameters& p, Pass&& pass) {
  switch (p.kernel) {
    case KernelKind::CubicSpline:
      pass(CubicSplineKernels<float>::make(p.h));
      break;
    case KernelKind::WendlandC2:
      pass(WendlandC2Kernels<float>::make(p.h));
      break;
    default:
      pass(MullerKernels<float>::make(p.h));
  }
}

}  // namespace sph::fluid
