// The scripted path of a kinematic object: keyframes of offset and rotation (axis × angle) from
// the initial pose about the initial centre of mass, linear in between, held after the last.
#pragma once

#include <utility>
#include <vector>

#include "objects/math3d.hpp"
#include "sph/scene.hpp"

namespace sph::objects {

struct KinematicPose {
  DVec3 offset;           // m
  Mat3 rotation;          // about the initial centre of mass
  DVec3 velocity;         // d offset / dt, m/s
  DVec3 angularVelocity;  // world frame, rad/s
};

class KinematicPath {
 public:
  KinematicPath() = default;
  // Keyframe times must be ≥ 0 and increasing (checked by validateKeyframes).
  explicit KinematicPath(std::vector<KeyframeDesc> keyframes);

  // The pose at time t and its derivative going forward from t (the segment that starts at or
  // contains t), so that contacts see the motion about to happen.
  KinematicPose at(double t) const;

  // From `now` on, a straight line from the pose at `now` to `offset` over `arriveIn` s
  // (> 0), the rotation held, then rest there: the path of an object a user drags.
  void steer(double now, const DVec3& offset, double arriveIn);

  // The keyframes as they stand (steering rewrites them): for a saved simulation state.
  const std::vector<KeyframeDesc>& keyframes() const { return keys_; }
  void setKeyframes(std::vector<KeyframeDesc> keys) { keys_ = std::move(keys); }

 private:
  // The keyframe values interpolated at t: offset and rotation vector.
  KeyframeDesc sample(double t) const;

  std::vector<KeyframeDesc> keys_;  // with the identity prepended at t = 0 when the first is later
};

// Throws InputError "<where>.keyframes[k].time: ..." for negative or non-increasing times.
void validateKeyframes(const std::vector<KeyframeDesc>& keyframes, const std::string& where);

}  // namespace sph::objects
