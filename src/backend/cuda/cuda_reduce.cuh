// Reductions on the GPU (thrust over a counting range): the time step's maxima and the
// statistics' sums.
#pragma once

#include <thrust/execution_policy.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/transform_reduce.h>

#include <cstddef>

#include "backend/cuda/cuda_check.hpp"

namespace sph::backend::cuda {

// combine over map(i), i in [0, n). `map` and `combine` are host/device functors.
template <class T, class Map, class Combine>
T reduce(std::size_t n, T identity, Map map, Combine combine) {
  const thrust::counting_iterator<std::size_t> first(0);
  const T result =
      thrust::transform_reduce(thrust::device, first, first + n, map, identity, combine);
  SPH_CUDA_CHECK(cudaGetLastError());
  return result;
}

}  // namespace sph::backend::cuda
