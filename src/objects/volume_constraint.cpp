#include "objects/volume_constraint.hpp"

#include <algorithm>
#include <utility>

namespace sph::objects {

namespace {

// A_k / A_rest: the mean of (l / l0)² over the particle's outer neighbours, 1 without any.
double areaStretch(const VolumeConstraint& c, std::size_t m, const std::vector<DVec3>& position) {
  const std::uint32_t begin = c.neighbourStart[m], end = c.neighbourStart[m + 1];
  if (begin == end) return 1.0;
  double sum = 0.0;
  for (std::uint32_t s = begin; s < end; ++s) {
    const DVec3 d = position[c.neighbour[s]] - position[c.surface[m]];
    sum += dot(d, d) / c.restDistance2[s];
  }
  return sum / double(end - begin);
}

DVec3 centroid(const VolumeConstraint& c, const std::vector<DVec3>& position) {
  DVec3 centre{0, 0, 0};
  for (std::uint32_t i : c.surface) centre += position[i];
  return centre / double(c.surface.size());
}

// (1/3) Σ_k (x_k − c) · n_k (A_k / A_rest).
double volumePerRestArea(const VolumeConstraint& c, const std::vector<DVec3>& position,
                         const std::vector<Vec3>& normal) {
  if (c.surface.empty()) return 0.0;
  const DVec3 centre = centroid(c, position);
  double sum = 0.0;
  for (std::size_t m = 0; m < c.surface.size(); ++m) {
    const std::uint32_t i = c.surface[m];
    sum += dot(position[i] - centre, toD(normal[i])) * areaStretch(c, m, position);
  }
  return sum / 3.0;
}

}  // namespace

VolumeConstraint makeVolumeConstraint(std::size_t object, std::size_t network,
                                      std::vector<std::uint32_t> surface, double volume,
                                      const std::vector<DVec3>& position,
                                      const std::vector<Vec3>& normal, std::size_t first,
                                      const std::vector<std::uint32_t>& neighbourStart,
                                      const std::vector<std::uint32_t>& neighbours) {
  VolumeConstraint c;
  c.object = object;
  c.network = network;
  c.surface = std::move(surface);
  c.neighbourStart.push_back(0);
  for (std::uint32_t i : c.surface) {
    const std::size_t k = i - first;
    for (std::uint32_t s = neighbourStart[k]; s < neighbourStart[k + 1]; ++s) {
      const std::uint32_t j = neighbours[s];
      // The surface is in ascending particle index.
      if (!std::binary_search(c.surface.begin(), c.surface.end(), j)) continue;
      const DVec3 d = position[j] - position[i];
      c.neighbour.push_back(j);
      c.restDistance2.push_back(dot(d, d));
    }
    c.neighbourStart.push_back(std::uint32_t(c.neighbour.size()));
  }
  const double perArea = volumePerRestArea(c, position, normal);
  c.restArea = perArea > 0.0 ? volume / perArea : 0.0;  // 0: no outward surface, nothing to keep
  c.restVolume = volume;
  return c;
}

double enclosedVolume(const VolumeConstraint& c, const std::vector<DVec3>& position,
                      const std::vector<Vec3>& normal) {
  return c.restArea * volumePerRestArea(c, position, normal);
}

void beginVolumeStep(VolumeConstraint& c, const std::vector<DVec3>& position,
                     const std::vector<Vec3>& normal, const std::vector<double>& inverseMass) {
  c.startPosition.resize(c.surface.size());
  c.gradient.resize(c.surface.size());
  c.startVolume = 0.0;
  c.weight = 0.0;
  if (c.surface.empty()) return;
  const DVec3 centre = centroid(c, position);
  for (std::size_t m = 0; m < c.surface.size(); ++m) {
    const std::uint32_t i = c.surface[m];
    c.startPosition[m] = position[i];
    c.gradient[m] = toD(normal[i]) * (c.restArea * areaStretch(c, m, position));
    c.startVolume += dot(position[i] - centre, c.gradient[m]) / 3.0;  // enclosedVolume's sum
    c.weight += inverseMass[i] * dot(c.gradient[m], c.gradient[m]);
  }
}

double linearisedVolume(const VolumeConstraint& c, const std::vector<DVec3>& position) {
  double v = c.startVolume;
  for (std::size_t m = 0; m < c.surface.size(); ++m)
    v += dot(c.gradient[m], position[c.surface[m]] - c.startPosition[m]);
  return v;
}

void projectVolume(const VolumeConstraint& c, const std::vector<double>& inverseMass,
                   std::vector<DVec3>& position) {
  if (!(c.weight > 0.0)) return;
  const double deltaLambda = -(linearisedVolume(c, position) - c.restVolume) / c.weight;
  for (std::size_t m = 0; m < c.surface.size(); ++m) {
    const std::uint32_t i = c.surface[m];
    position[i] += c.gradient[m] * (inverseMass[i] * deltaLambda);
  }
}

}  // namespace sph::objects
