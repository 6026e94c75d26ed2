#include "sph/object_exchange.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace sph {

void ObjectSurface::clear() {
  position.clear();
  velocity.clear();
  normal.clear();
  handle.clear();
  object.clear();
  cut.clear();
}

void ObjectSurface::add(Vec3 x, Vec3 v, float radius, Vec3 n, std::uint32_t h, std::int32_t o,
                        bool isCut) {
  position.push_back(makeVec4(x, radius));
  velocity.push_back(makeVec4(v));
  normal.push_back(makeVec4(n));
  handle.push_back(h);
  object.push_back(o);
  cut.push_back(isCut ? 1 : 0);
}

ObjectExchange::ObjectExchange(std::size_t handleCount)
    : handleCount_(handleCount),
      impulse_(handleCount, Vec3{0, 0, 0}),
      lastMean_(handleCount, Vec3{0, 0, 0}) {}

void ObjectExchange::publish() {
  const std::size_t n = back_.handle.size();
  if (back_.position.size() != n || back_.velocity.size() != n || back_.normal.size() != n ||
      back_.object.size() != n || back_.cut.size() != n)
    throw std::invalid_argument(
        "ObjectExchange::publish: the surface's arrays differ in length (fill it with add)");
  for (std::size_t k = 0; k < n; ++k) {
    if (back_.handle[k] >= handleCount_)
      throw std::out_of_range("ObjectExchange::publish: handle " + std::to_string(back_.handle[k]) +
                              " is not below the handle count " + std::to_string(handleCount_));
    if (back_.object[k] < 0)
      throw std::out_of_range("ObjectExchange::publish: object id " +
                              std::to_string(back_.object[k]) + " is negative");
  }
  {
    std::lock_guard<std::mutex> lock(frontMutex_);
    std::swap(front_, back_);
    ++version_;
    announced_ = false;
  }
  published_.notify_all();
}

void ObjectExchange::announce(bool coming) {
  {
    std::lock_guard<std::mutex> lock(frontMutex_);
    announced_ = coming;
  }
  published_.notify_all();
}

double ObjectExchange::takeForces(std::vector<Vec3>& forceByHandle) {
  std::lock_guard<std::mutex> lock(forceMutex_);
  const double span = span_;
  if (span > 0.0) {
    const float inverse = static_cast<float>(1.0 / span);
    for (std::size_t h = 0; h < handleCount_; ++h) {
      lastMean_[h] = impulse_[h] * inverse;
      impulse_[h] = Vec3{0, 0, 0};
    }
    span_ = 0.0;
  }
  forceByHandle = lastMean_;
  return span;
}

void ObjectExchange::depositForces(const std::uint32_t* handle, const Vec4* force,
                                   std::size_t count, double dt) {
  const float step = static_cast<float>(dt);
  std::lock_guard<std::mutex> lock(forceMutex_);
  for (std::size_t k = 0; k < count; ++k) impulse_[handle[k]] += xyz(force[k]) * step;
  span_ += dt;
}

ObjectExchange::Snapshot ObjectExchange::snapshot() {
  Snapshot s;
  {
    std::lock_guard<std::mutex> lock(frontMutex_);
    s.front = front_;
    s.version = version_;
  }
  std::lock_guard<std::mutex> lock(forceMutex_);
  s.impulse = impulse_;
  s.span = span_;
  s.lastMean = lastMean_;
  return s;
}

void ObjectExchange::restore(Snapshot s) {
  if (s.impulse.size() != handleCount_ || s.lastMean.size() != handleCount_)
    throw std::invalid_argument("ObjectExchange::restore: forces for " +
                                std::to_string(s.impulse.size()) + " handles, not " +
                                std::to_string(handleCount_));
  for (std::uint32_t h : s.front.handle)
    if (h >= handleCount_)
      throw std::invalid_argument("ObjectExchange::restore: handle " + std::to_string(h) +
                                  " is not below the handle count " + std::to_string(handleCount_));
  {
    std::lock_guard<std::mutex> lock(frontMutex_);
    front_ = std::move(s.front);
    version_ = s.version;
  }
  std::lock_guard<std::mutex> lock(forceMutex_);
  impulse_ = std::move(s.impulse);
  span_ = s.span;
  lastMean_ = std::move(s.lastMean);
}

}  // namespace sph
