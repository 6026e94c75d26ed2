#include "sim/object_runner.hpp"

#include <cmath>
#include <utility>

#include "backend/cpu_parallel.hpp"

namespace sph::sim {

ObjectRunner::ObjectRunner(objects::ObjectWorld world, double rate, bool ownThread)
    : world_(std::move(world)),
      exchange_(world_.particles().size()),
      rate_(rate),
      ownThread_(ownThread) {
  publishSurface();
  if (ownThread_) thread_ = std::thread([this] { engineLoop(); });
}

ObjectRunner::~ObjectRunner() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void ObjectRunner::advance(double dt) {
  if (!ownThread_) {
    engineStep(dt);
    return;
  }
  wait();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    jobDt_ = dt;
    busy_ = true;
  }
  wake_.notify_all();
}

void ObjectRunner::wait() const {
  if (!ownThread_) return;
  std::unique_lock<std::mutex> lock(mutex_);
  wake_.wait(lock, [this] { return !busy_; });
  if (error_) std::rethrow_exception(error_);
}

void ObjectRunner::engineLoop() {
  backend::runSeriallyOnThisThread();  // the engine is serial; beside the fluid's threads
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return busy_ || stopping_; });
    if (stopping_) return;
    const double dt = jobDt_;
    lock.unlock();
    std::exception_ptr error;
    try {
      engineStep(dt);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    if (error) error_ = error;
    busy_ = false;
    wake_.notify_all();
  }
}

void ObjectRunner::engineStep(double dt) {
  pendingTime_ += dt;
  credit_ += rate_;
  // The small allowance keeps a rate such as 1/3 from losing a step to rounding.
  const double steps = std::floor(credit_ + 1e-9);
  if (steps < 1.0) return;
  credit_ -= steps;
  exchange_.takeForces(forces_);
  const double substep = pendingTime_ / steps;
  pendingTime_ = 0.0;
  for (int k = 0; k < int(steps); ++k) world_.step(substep, forces_);
  publishSurface();
}

void ObjectRunner::publishSurface() {
  const objects::ParticleState& p = world_.particles();
  ObjectSurface& out = exchange_.back();
  out.clear();
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (!p.surface[k]) continue;
    out.add(p.position[k], p.velocity[k], p.radius[k], p.normal[k], std::uint32_t(k), p.object[k],
            p.cut[k] != 0);
  }
  out.time = world_.time();
  exchange_.publish();
}

}  // namespace sph::sim
