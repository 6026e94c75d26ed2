#include "soft_bodies.hpp"

#include <BulletSoftBody/btSoftBodyHelpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace sph::bullet {
namespace {

using Triangle = std::array<int, 3>;

// The unit icosahedron, its faces counter-clockwise seen from outside.
void icosahedron(std::vector<btVector3>& vertex, std::vector<Triangle>& face) {
  const btScalar t = btScalar((1.0 + std::sqrt(5.0)) / 2.0);
  vertex = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
            {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (btVector3& v : vertex) v.normalize();
  face = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
          {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
          {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
}

// Each triangle into four, the new vertices pushed out onto the unit sphere.
void subdivide(std::vector<btVector3>& vertex, std::vector<Triangle>& face) {
  std::map<std::pair<int, int>, int> midpoint;
  const auto middle = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto found = midpoint.find(key);
    if (found != midpoint.end()) return found->second;
    vertex.push_back((vertex[std::size_t(a)] + vertex[std::size_t(b)]).normalized());
    return midpoint[key] = int(vertex.size()) - 1;
  };
  std::vector<Triangle> finer;
  finer.reserve(4 * face.size());
  for (const Triangle& f : face) {
    const int ab = middle(f[0], f[1]), bc = middle(f[1], f[2]), ca = middle(f[2], f[0]);
    finer.push_back({f[0], ab, ca});
    finer.push_back({f[1], bc, ab});
    finer.push_back({f[2], ca, bc});
    finer.push_back({ab, bc, ca});
  }
  face = std::move(finer);
}

double longestEdge(const std::vector<btVector3>& vertex, const std::vector<Triangle>& face) {
  double longest = 0.0;
  for (const Triangle& f : face)
    for (int k = 0; k < 3; ++k)
      longest = std::max(
          longest, double(vertex[std::size_t(f[k])].distance(vertex[std::size_t(f[(k + 1) % 3])])));
  return longest;
}

void refuse(const std::string& what) {
  throw std::invalid_argument("BulletEngine: " + what);
}

}  // namespace

std::unique_ptr<btSoftBody> makeSoftBall(btSoftBodyWorldInfo& world, double radius,
                                         const btVector3& centre, double mass, double spacing) {
  if (!(radius >= spacing)) refuse("a soft ball's radius must be at least a spacing");
  std::vector<btVector3> unit;
  std::vector<Triangle> face;
  icosahedron(unit, face);
  while (longestEdge(unit, face) * radius > spacing) subdivide(unit, face);
  std::vector<btVector3> x;
  for (const btVector3& u : unit) x.push_back(centre + u * btScalar(radius));
  const std::vector<btScalar> m(x.size(), btScalar(mass / double(x.size())));
  auto body = std::make_unique<btSoftBody>(&world, int(x.size()), x.data(), m.data());
  std::set<std::pair<int, int>> linked;
  for (const Triangle& f : face) {
    for (int k = 0; k < 3; ++k) {
      const auto edge = std::minmax(f[k], f[(k + 1) % 3]);
      if (linked.insert(edge).second) body->appendLink(edge.first, edge.second);
    }
    body->appendFace(f[0], f[1], f[2]);
  }
  return body;
}

std::unique_ptr<btSoftBody> makeRope(btSoftBodyWorldInfo& world, const btVector3& from,
                                     const btVector3& to, double mass, double spacing,
                                     unsigned pinned) {
  const int nodes = std::max(2, int(std::ceil(double(from.distance(to)) / spacing - 1e-4)) + 1);
  std::unique_ptr<btSoftBody> body(
      btSoftBodyHelpers::CreateRope(world, from, to, nodes - 2, int(pinned & 3u)));
  body->setTotalMass(btScalar(mass));
  return body;
}

std::unique_ptr<btSoftBody> makeCloth(btSoftBodyWorldInfo& world, const btVector3& corner,
                                      const btVector3& edgeU, const btVector3& edgeV, double mass,
                                      double spacing, unsigned pinned) {
  const auto nodesAlong = [&](const btVector3& edge) {
    return std::max(2, int(std::ceil(double(edge.length()) / spacing - 1e-4)) + 1);
  };
  std::unique_ptr<btSoftBody> body(btSoftBodyHelpers::CreatePatch(
      world, corner, corner + edgeU, corner + edgeV, corner + edgeU + edgeV, nodesAlong(edgeU),
      nodesAlong(edgeV), int(pinned & 15u), true));
  body->setTotalMass(btScalar(mass));
  return body;
}

void applyMaterial(btSoftBody& body, const BulletEngine::SoftMaterial& m, double spacing) {
  if (!(m.stiffness > 0.0 && m.stiffness <= 1.0))
    refuse("a soft material's stiffness must be in (0, 1]");
  if (!(m.bendingStiffness >= 0.0 && m.bendingStiffness <= 1.0))
    refuse("a soft material's bending stiffness must be in [0, 1]");
  if (!(m.damping >= 0.0 && m.damping <= 1.0))
    refuse("a soft material's damping must be in [0, 1]");
  if (!std::isfinite(m.pressure)) refuse("a soft material's pressure must be finite");
  if (!(m.volumeStiffness >= 0.0)) refuse("a soft material's volume stiffness must be >= 0");
  if (!(m.breakingStrain >= 0.0))
    refuse("a soft material's breaking strain must be >= 0 (0: never)");
  if (m.iterations < 1 || m.iterations > 100)
    refuse("a soft material's iterations must be in [1, 100]");
  // Torn, a closed volume's faces would still be pressed as if it were closed.
  if (m.breakingStrain > 0.0 && (m.pressure != 0.0 || m.volumeStiffness != 0.0))
    refuse("a soft body that tears can have no pressure or volume stiffness");
  body.m_materials[0]->m_kLST = btScalar(m.stiffness);
  if (m.bendingStiffness > 0.0) {
    btSoftBody::Material* bending = body.appendMaterial();
    bending->m_kLST = btScalar(m.bendingStiffness);
    body.generateBendingConstraints(2, bending);
  }
  body.m_cfg.piterations = m.iterations;
  body.m_cfg.kDP = btScalar(m.damping);
  body.m_cfg.kPR = btScalar(m.pressure);
  body.m_cfg.kVC = btScalar(m.volumeStiffness);
  if (m.volumeStiffness > 0.0) body.setPose(true, false);  // its rest volume, to keep
  body.getCollisionShape()->setMargin(btScalar(0.5 * spacing));
}

std::size_t tearOverstretchedLinks(btSoftBody& body, double breakingStrain,
                                   std::vector<std::uint8_t>& cut) {
  if (!(breakingStrain > 0.0)) return 0;
  std::size_t torn = 0;
  const btSoftBody::Node* first = &body.m_nodes[0];
  for (int i = body.m_links.size() - 1; i >= 0; --i) {
    const btSoftBody::Link& link = body.m_links[i];
    const double length = link.m_n[0]->m_x.distance(link.m_n[1]->m_x);
    if (length <= (1.0 + breakingStrain) * double(link.m_rl)) continue;
    cut[std::size_t(link.m_n[0] - first)] = cut[std::size_t(link.m_n[1] - first)] = 1;
    body.m_links.swap(i, body.m_links.size() - 1);
    body.m_links.pop_back();
    ++torn;
  }
  if (torn > 0) body.m_bUpdateRtCst = true;
  return torn;
}

}  // namespace sph::bullet
