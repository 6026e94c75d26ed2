// The public door to the CPU backend's thread settings (sph/threads.hpp).
#include "sph/threads.hpp"

#include "backend/cpu_parallel.hpp"

namespace sph {

int threadCount() {
  return backend::threadCount();
}
void setThreadCount(int n) {
  backend::setThreadCount(n);
}
void runSeriallyOnThisThread() {
  backend::runSeriallyOnThisThread();
}

}  // namespace sph
