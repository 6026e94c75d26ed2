#include "objects/kinematic_path.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "objects/shape_sampling.hpp"
#include "sph/error.hpp"

namespace sph::objects {

KinematicPath::KinematicPath(std::vector<KeyframeDesc> keyframes) : keys_(std::move(keyframes)) {
  if (!keys_.empty() && keys_.front().time > 0.0) keys_.insert(keys_.begin(), KeyframeDesc{});
}

KinematicPose KinematicPath::at(double t) const {
  KinematicPose pose{{0, 0, 0}, Mat3::identity(), {0, 0, 0}, {0, 0, 0}};
  if (keys_.empty()) return pose;
  if (t >= keys_.back().time || keys_.size() == 1) {
    const KeyframeDesc& last = t >= keys_.back().time ? keys_.back() : keys_.front();
    pose.offset = toD(last.offset);
    pose.rotation = rotationFromVector(toD(last.rotation));
    return pose;
  }
  std::size_t k = 0;
  while (k + 2 < keys_.size() && t >= keys_[k + 1].time) ++k;
  const KeyframeDesc& a = keys_[k];
  const KeyframeDesc& b = keys_[k + 1];
  const double duration = b.time - a.time;
  const double alpha = std::max(0.0, (t - a.time) / duration);
  const DVec3 theta0 = toD(a.rotation), theta1 = toD(b.rotation);
  const DVec3 theta = theta0 + (theta1 - theta0) * alpha;
  pose.offset = toD(a.offset) + (toD(b.offset) - toD(a.offset)) * alpha;
  pose.rotation = rotationFromVector(theta);
  pose.velocity = (toD(b.offset) - toD(a.offset)) / duration;
  pose.angularVelocity = leftJacobian(theta) * ((theta1 - theta0) / duration);
  return pose;
}

KeyframeDesc KinematicPath::sample(double t) const {
  KeyframeDesc out;
  out.time = t;
  if (keys_.empty()) return out;
  if (t >= keys_.back().time || keys_.size() == 1) {
    const KeyframeDesc& last = t >= keys_.back().time ? keys_.back() : keys_.front();
    out.offset = last.offset;
    out.rotation = last.rotation;
    return out;
  }
  std::size_t k = 0;
  while (k + 2 < keys_.size() && t >= keys_[k + 1].time) ++k;
  const KeyframeDesc& a = keys_[k];
  const KeyframeDesc& b = keys_[k + 1];
  const double alpha = std::max(0.0, (t - a.time) / (b.time - a.time));
  for (int i = 0; i < 3; ++i) {
    out.offset[i] = a.offset[i] + (b.offset[i] - a.offset[i]) * alpha;
    out.rotation[i] = a.rotation[i] + (b.rotation[i] - a.rotation[i]) * alpha;
  }
  return out;
}

void KinematicPath::steer(double now, const DVec3& offset, double arriveIn) {
  const KeyframeDesc from = sample(now);
  KeyframeDesc to = from;
  to.time = now + arriveIn;
  to.offset = {offset.x, offset.y, offset.z};
  keys_ = {from, to};
}

void validateKeyframes(const std::vector<KeyframeDesc>& keyframes, const std::string& where) {
  for (std::size_t k = 0; k < keyframes.size(); ++k) {
    const double t = keyframes[k].time;
    const std::string key = where + ".keyframes[" + std::to_string(k) + "].time: ";
    if (!(t >= 0.0) || !std::isfinite(t))
      throw InputError(key + "expected a time ≥ 0, got " + formatNumber(t));
    if (k > 0 && !(t > keyframes[k - 1].time))
      throw InputError(key + "expected times in increasing order, got " + formatNumber(t) +
                       " after " + formatNumber(keyframes[k - 1].time));
  }
}

}  // namespace sph::objects
