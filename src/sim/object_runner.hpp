// Runs the built-in object engine beside the fluid (Meteer 2011, figure 1): in its own thread by
// default, in lock-step — the fluid hands it each step's length and collects its publication
// at the next step's interaction — so that runs stay byte-identical. Between the two, the
// engine steps while the fluid builds its grid and computes densities and forces.
//
// `rate` is engine steps per fluid step: 2 takes two half steps per fluid step; 0.5 takes one
// step every second fluid step, over both, with the mean of the forces deposited meanwhile.
#pragma once

#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "objects/object_world.hpp"
#include "sph/object_exchange.hpp"

namespace sph::sim {

class ObjectRunner {
 public:
  ObjectRunner(objects::ObjectWorld world, double rate, bool ownThread);
  ~ObjectRunner();
  ObjectRunner(const ObjectRunner&) = delete;
  ObjectRunner& operator=(const ObjectRunner&) = delete;

  ObjectExchange& exchange() { return exchange_; }
  // The engine's state; call wait() first.
  const objects::ObjectWorld& world() const { return world_; }
  objects::ObjectWorld& world() { return world_; }

  // The fluid has taken a step of length dt and deposited its forces: the engine does its part
  // (in its thread, returning at once, or here).
  void advance(double dt);
  // Until the engine has finished its part of the last step. Rethrows what the engine threw.
  void wait() const;

  // The engine's pacing between fluid steps (rate ≠ 1), for a saved simulation state; call
  // wait() first.
  struct Pacing {
    double credit = 0.0;
    double pendingTime = 0.0;
  };
  Pacing pacing() const { return {credit_, pendingTime_}; }
  void setPacing(const Pacing& p) {
    credit_ = p.credit;
    pendingTime_ = p.pendingTime;
  }

 private:
  void engineLoop();
  void engineStep(double dt);
  void publishSurface();

  objects::ObjectWorld world_;
  ObjectExchange exchange_;
  double rate_;
  double credit_ = 0.0;       // engine steps owed
  double pendingTime_ = 0.0;  // fluid time the engine has not yet stepped over, s
  std::vector<Vec3> forces_;

  bool ownThread_;
  mutable std::mutex mutex_;
  mutable std::condition_variable wake_;
  bool busy_ = false;
  bool stopping_ = false;
  double jobDt_ = 0.0;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace sph::sim
