#include "objects/springs.hpp"

#include <algorithm>
#include <cmath>

#include "objects/point_grid.hpp"
#include "sph/core/contact.hpp"

namespace sph::objects {

namespace {

// The orthonormal frame (t1, t2, t3) of a particle at x from its two frame neighbours.
void localFrame(DVec3 x, DVec3 xa, DVec3 xb, DVec3& t1, DVec3& t2, DVec3& t3) {
  t1 = normalized(xa - x);
  t3 = normalized(cross(t1, xb - x));
  t2 = cross(t3, t1);
}

// Among the rest neighbours of particle i that lie roughly in its tangent plane, the pair whose
// cross product is best aligned with the rest normal (|sin angle| × alignment above 0.5).
NormalFrame pickFrame(std::size_t i, const std::vector<std::uint32_t>& neighbours,
                      const std::vector<DVec3>& position, DVec3 n) {
  std::vector<std::uint32_t> tangential;
  for (std::uint32_t j : neighbours) {
    const DVec3 d = normalized(position[j] - position[i]);
    if (std::abs(dot(d, n)) < 0.5) tangential.push_back(j);
  }
  NormalFrame best;
  double bestScore = 0.5;
  for (std::size_t p = 0; p < tangential.size(); ++p)
    for (std::size_t q = p + 1; q < tangential.size(); ++q) {
      const DVec3 da = position[tangential[p]] - position[i];
      const DVec3 db = position[tangential[q]] - position[i];
      const double alignment = dot(cross(da, db), n) / (norm(da) * norm(db));
      if (std::abs(alignment) > bestScore) {
        bestScore = std::abs(alignment);
        best.a = tangential[p];
        best.b = tangential[q];
        best.valid = true;
      }
    }
  if (best.valid) {
    DVec3 t1, t2, t3;
    localFrame(position[i], position[best.a], position[best.b], t1, t2, t3);
    best.coefficients = {dot(n, t1), dot(n, t2), dot(n, t3)};
  }
  return best;
}

// Which way is out near particle i: its rest normal carried by its frame of two neighbours,
// which turns with the surface (and so cannot flip sign without the surface folding through
// itself there); the rest normal where there is no frame.
DVec3 orientation(const NormalFrame& f, const std::vector<DVec3>& position, DVec3 restNormal,
                  std::size_t i) {
  if (!f.valid) return restNormal;
  DVec3 t1, t2, t3;
  localFrame(position[i], position[f.a], position[f.b], t1, t2, t3);
  const DVec3 c = f.coefficients;
  return t1 * c.x + t2 * c.y + t3 * c.z;
}

}  // namespace

SpringNetwork buildSprings(const std::vector<DVec3>& position, const std::vector<DVec3>& normal,
                           std::size_t first, std::size_t count, double reach) {
  SpringNetwork net;
  net.first = first;
  net.count = count;
  const std::vector<DVec3> points(position.begin() + first, position.begin() + first + count);
  PointGrid grid;
  grid.build(points, reach);
  net.neighbourStart.push_back(0);
  net.frames.resize(count);
  std::vector<std::uint32_t> neighbours;
  for (std::size_t i = 0; i < count; ++i) {
    neighbours.clear();
    grid.forEachCandidate(points[i], reach, [&](std::uint32_t j) {
      if (j != i && norm(points[j] - points[i]) < reach) neighbours.push_back(j);
    });
    std::sort(neighbours.begin(), neighbours.end());
    for (std::uint32_t j : neighbours) {
      if (j < i) continue;
      const std::uint32_t a = std::uint32_t(first + i), b = std::uint32_t(first + j);
      net.springs.push_back({a, b, norm(points[j] - points[i])});
      net.broken.push_back(0);
    }
    NormalFrame frame = pickFrame(i, neighbours, points, normal[first + i]);
    frame.a += std::uint32_t(first);
    frame.b += std::uint32_t(first);
    net.frames[i] = frame;
    for (std::uint32_t j : neighbours) net.neighbours.push_back(std::uint32_t(first + j));
    net.neighbourStart.push_back(std::uint32_t(net.neighbours.size()));
  }
  return net;
}

void addSpringForces(const SpringNetwork& net, const std::vector<DVec3>& position,
                     const std::vector<DVec3>& velocity, std::vector<DVec3>& force) {
  for (std::size_t s = 0; s < net.springs.size(); ++s) {
    if (net.broken[s]) continue;
    const Spring& spring = net.springs[s];
    const DVec3 d = position[spring.b] - position[spring.a];
    const double l = norm(d);
    if (l <= 0.0) continue;
    const DVec3 u = d / l;
    const double magnitude = springTension(net.stiffness, net.damping, l, spring.restLength,
                                           dot(velocity[spring.b] - velocity[spring.a], u));
    force[spring.a] += u * magnitude;
    force[spring.b] -= u * magnitude;
  }
}

void breakOverstretched(SpringNetwork& net, const std::vector<DVec3>& position,
                        std::vector<std::uint8_t>& cut) {
  if (!(net.breakingStrain > 0.0)) return;
  for (std::size_t s = 0; s < net.springs.size(); ++s) {
    if (net.broken[s]) continue;
    const Spring& spring = net.springs[s];
    const double l = norm(position[spring.b] - position[spring.a]);
    if (std::abs(l - spring.restLength) > net.breakingStrain * spring.restLength) {
      net.broken[s] = 1;
      ++net.brokenCount;
      cut[spring.a] = cut[spring.b] = 1;
    }
  }
}

void updateNormals(const SpringNetwork& net, const std::vector<DVec3>& position,
                   const std::vector<DVec3>& restNormal, const std::vector<std::uint8_t>& pinned,
                   std::vector<Vec3>& normal) {
  std::vector<DVec3> own(net.count);
  for (std::size_t k = 0; k < net.count; ++k) {
    const std::size_t i = net.first + k;
    own[k] = pinned[i] ? restNormal[i]
                       : normalized(orientation(net.frames[k], position, restNormal[i], i));
  }
  // On a sharp crease a particle's two frame neighbours can turn edge-on and its normal point
  // anywhere; one more than 60° from the mean of its neighbours' is replaced by that mean.
  const double agreement = 0.5;  // cos 60°
  for (std::size_t k = 0; k < net.count; ++k) {
    const std::size_t i = net.first + k;
    DVec3 mean{0, 0, 0};
    for (std::uint32_t s = net.neighbourStart[k]; s < net.neighbourStart[k + 1]; ++s)
      mean += own[net.neighbours[s] - net.first];
    const bool outlier =
        !pinned[i] && norm(mean) > 0.0 && dot(own[k], normalized(mean)) < agreement;
    normal[i] = toF(outlier ? normalized(mean) : own[k]);
  }
}

}  // namespace sph::objects
