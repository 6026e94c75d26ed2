// The exchange between the fluid and a physics engine for particle-based objects (Meteer 2011,
// §4.3, §7.2, figure 1). Any engine that can publish its objects' surface particles and accept
// forces on them can be coupled: the built-in one (src/objects) or your own.
//
// Both directions are double-buffered, so the engine may run in its own thread at its own
// rate. The engine fills `back()` and calls `publish()`; the fluid reads the newest publication
// at its next step. The fluid deposits the contact force on each surface particle at every
// fluid step; the forces accumulate as impulses until the engine takes them, as the mean force
// over the time they span.
//
//   // engine thread, each engine step:
//   double span = exchange.takeForces(forces);   // N, by handle
//   engine.step(dt, forces);
//   ObjectSurface& s = exchange.back();
//   s.clear(); for (each surface particle) s.add(...);
//   exchange.publish();
#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

#include "sph/core/vec.hpp"

namespace sph {

// The surface particles of every object, as an engine publishes them.
struct ObjectSurface {
  std::vector<Vec4> position;         // xyz (m); w: particle radius (m)
  std::vector<Vec4> velocity;         // xyz (m/s); w unused
  std::vector<Vec4> normal;           // outward unit normal of the object at the particle
  std::vector<std::uint32_t> handle;  // the engine's index: forces come back by it
  std::vector<std::int32_t> object;   // object id, 0-based
  std::vector<std::uint8_t> cut;      // 1: the object is torn here (no contact damping)
  double time = 0.0;                  // the engine's time, s

  std::size_t size() const { return handle.size(); }
  void clear();
  void add(Vec3 position, Vec3 velocity, float radius, Vec3 normal, std::uint32_t handle,
           std::int32_t object, bool cut);
};

class ObjectExchange {
 public:
  // Handles run from 0 to handleCount - 1.
  explicit ObjectExchange(std::size_t handleCount);
  std::size_t handleCount() const { return handleCount_; }

  // --- the engine's side ---
  // The buffer to fill; only the engine touches it until publish().
  ObjectSurface& back() { return back_; }
  // Makes back() the publication the fluid reads next. Throws std::out_of_range on a handle
  // not below handleCount() or a negative object id, std::invalid_argument when the arrays
  // differ in length; nothing is published then.
  void publish();
  // The mean force (N) on each particle, by handle, over the fluid steps deposited since the
  // last call; returns the time they span (s). When no fluid step was deposited since, gives
  // the previous mean again and returns 0.
  double takeForces(std::vector<Vec3>& forceByHandle);
  // Lock-step with an engine in a thread of its own: having taken a step's forces, the engine
  // announces the publication it will make of them, and the fluid's next readIfNew waits for
  // it, so that each fluid step reads what the engine made of the one before, as if the two
  // ran one after the other. announce(false) withdraws an announcement (an engine step failed).
  void announce(bool coming = true);

  // --- the fluid's side ---
  // Calls read(const ObjectSurface&) on the newest publication, if it is newer than
  // `seenVersion`, and updates `seenVersion`. Returns whether it read one.
  template <class Read>
  bool readIfNew(std::uint64_t& seenVersion, Read&& read) {
    std::unique_lock<std::mutex> lock(frontMutex_);
    published_.wait(lock, [&] { return !announced_; });
    if (version_ == seenVersion) return false;
    read(static_cast<const ObjectSurface&>(front_));
    seenVersion = version_;
    return true;
  }
  // Adds force[k] × dt to the impulse of particle handle[k], for k < count.
  void depositForces(const std::uint32_t* handle, const Vec4* force, std::size_t count, double dt);

  // --- a saved simulation state (Simulation::saveState), with neither side in a call ---
  struct Snapshot {
    ObjectSurface front;  // the newest publication
    std::uint64_t version = 0;
    std::vector<Vec3> impulse;   // by handle, since the last take
    double span = 0.0;           // s
    std::vector<Vec3> lastMean;  // by handle
  };
  Snapshot snapshot();
  // Throws std::invalid_argument when the snapshot's handles are not this exchange's.
  void restore(Snapshot snapshot);

 private:
  std::size_t handleCount_;
  ObjectSurface back_;
  ObjectSurface front_;
  std::uint64_t version_ = 0;
  std::mutex frontMutex_;
  bool announced_ = false;
  std::condition_variable published_;

  std::vector<Vec3> impulse_;  // N·s, by handle, since the last take
  double span_ = 0.0;
  std::vector<Vec3> lastMean_;
  std::mutex forceMutex_;
};

}  // namespace sph
