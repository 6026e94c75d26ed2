// One execution-space macro for every function that runs on both the CPU and the GPU.
#pragma once

#if defined(__CUDACC__)
#define SPH_HD __host__ __device__ __forceinline__
#else
#define SPH_HD inline
#endif

// The same, always inlined on the CPU too: the small terms inside neighbour loops, where GCC
// otherwise leaves some as calls.
#if defined(__CUDACC__)
#define SPH_HD_INLINE __host__ __device__ __forceinline__
#else
#define SPH_HD_INLINE inline __attribute__((always_inline))
#endif

// A per-particle functor written once for both backends: captures by value.
#if defined(__CUDACC__)
#define SPH_LAMBDA [=] __host__ __device__
#else
#define SPH_LAMBDA [=]
#endif
