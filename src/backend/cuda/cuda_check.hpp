// Every CUDA runtime call goes through SPH_CUDA_CHECK: an error becomes an exception that names
// the call and where it was made.
#pragma once

#include <cuda_runtime.h>

#include <stdexcept>
#include <string>

namespace sph::backend::cuda {

class CudaError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws CudaError("CALL failed at FILE:LINE: NAME (DESCRIPTION)") unless `status` is success.
void check(cudaError_t status, const char* call, const char* file, int line);

}  // namespace sph::backend::cuda

#define SPH_CUDA_CHECK(call) ::sph::backend::cuda::check((call), #call, __FILE__, __LINE__)
