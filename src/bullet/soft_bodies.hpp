// Bullet's soft bodies for the adapter (sph/bullet_engine.hpp): their meshes, a node about a
// spacing apart so that the fluid's particles cannot pass between them, their material, and
// their tearing.
#pragma once

#include <BulletSoftBody/btSoftBody.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "sph/bullet_engine.hpp"

namespace sph::bullet {

// A closed ball: an icosahedron subdivided until no edge is longer than `spacing`, on the
// sphere, its faces counter-clockwise seen from outside; `mass` shared by its nodes.
std::unique_ptr<btSoftBody> makeSoftBall(btSoftBodyWorldInfo& world, double radius,
                                         const btVector3& centre, double mass, double spacing);
// A rope, its nodes at most `spacing` apart; `pinned` as BulletEngine::addRope.
std::unique_ptr<btSoftBody> makeRope(btSoftBodyWorldInfo& world, const btVector3& from,
                                     const btVector3& to, double mass, double spacing,
                                     unsigned pinned);
// A cloth over the parallelogram corner + s·edgeU + t·edgeV, s, t in [0, 1].
std::unique_ptr<btSoftBody> makeCloth(btSoftBodyWorldInfo& world, const btVector3& corner,
                                      const btVector3& edgeU, const btVector3& edgeV, double mass,
                                      double spacing, unsigned pinned);

// Stiffness, bending links, pressure, iterations and collision margin from the material;
// throws std::invalid_argument naming what is out of range.
void applyMaterial(btSoftBody& body, const BulletEngine::SoftMaterial& material, double spacing);

// Removes every link stretched past (1 + breakingStrain) × its rest length and marks its two
// nodes in `cut`; returns how many it removed.
std::size_t tearOverstretchedLinks(btSoftBody& body, double breakingStrain,
                                   std::vector<std::uint8_t>& cut);

}  // namespace sph::bullet
