// Loads of what a kernel only reads, in its neighbour loops: through the GPU's read-only data
// cache (Meteer 2011 used texture fetches on the GTX 480, §5; `__ldg` is their successor),
// plain loads on the CPU. The arrays are reordered by cell, so neighbours share cache lines.
#pragma once

#include <cstdint>

#include "sph/core/vec.hpp"

namespace sph {

SPH_HD Vec4 readOnly(const Vec4* p) {
#if defined(__CUDA_ARCH__)
  const float4 v = __ldg(reinterpret_cast<const float4*>(p));  // Vec4 is 16-byte aligned
  return Vec4{v.x, v.y, v.z, v.w};
#else
  return *p;
#endif
}

SPH_HD float readOnly(const float* p) {
#if defined(__CUDA_ARCH__)
  return __ldg(p);
#else
  return *p;
#endif
}

SPH_HD std::uint32_t readOnly(const std::uint32_t* p) {
#if defined(__CUDA_ARCH__)
  return __ldg(reinterpret_cast<const unsigned int*>(p));
#else
  return *p;
#endif
}

}  // namespace sph
