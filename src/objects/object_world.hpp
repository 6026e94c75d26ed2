// The built-in engine for particle-based objects (Meteer 2011, §4.3): rigid bodies
// (Newton–Euler), deformables (particles joined by springs that can break: explicit forces or
// XPBD constraints), pinned particles and kinematic actuators that follow keyframes. Runs on the
// host; the fluid sees only the surface particles it publishes and returns forces on them
// (interaction/exchange).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "objects/drawn_surface.hpp"
#include "objects/periodic_space.hpp"
#include "sph/core/contact.hpp"
#include "sph/core/vec.hpp"
#include "sph/scene.hpp"

namespace sph::objects {

struct WorldSettings {
  Vec3 gravity{0.0f, 0.0f, 0.0f};
  float defaultSpacing = 0.0f;  // for objects whose spacing is 0 (the fluid's spacing)
  // Object–object contact between particles of different objects (DEM, core/contact.hpp).
  ContactCoefficients contact{0.0f, 0.0f, 0.0f};
  // Static geometry the objects collide with (the fluid's walls): fixed particles of this
  // radius that push movable particles by the same contact law and never move.
  std::vector<Vec3> staticParticles;
  float staticRadius = 0.0f;
  // Where the objects can touch anything (the fluid's domain): a particle outside it, such as a
  // piece torn off and falling away, bounds no substep with its speed.
  Vec3 regionMin{-3.0e38f, -3.0e38f, -3.0e38f};
  Vec3 regionMax{3.0e38f, 3.0e38f, 3.0e38f};
  // The fluid's periodic axes (the region is unbounded along them): objects meet across a
  // periodic face, and one whose centre leaves through a face comes back whole through the
  // other.
  PeriodicSpace periodic;
  // Objects filled with an incompressible liquid, by index: each one that is a closed XPBD
  // deformable keeps the volume it encloses until it tears (volume_constraint.hpp).
  std::vector<std::size_t> liquidFilled;
  std::string sceneFolder;  // mesh files are resolved against it
  std::string sourceName;   // the scene file, for error messages
};

// Every particle of every object, by particle index (stable: the index is the particle's
// handle in the exchange). Objects occupy consecutive ranges.
struct ParticleState {
  std::vector<Vec3> position;  // m
  std::vector<Vec3> velocity;  // m/s
  std::vector<Vec3> normal;    // outward unit normal of the object's surface at the particle
  std::vector<float> mass;     // kg
  std::vector<float> radius;   // half the object's spacing, m
  std::vector<std::int32_t> object;
  std::vector<std::uint8_t> surface;  // 1: on the object's surface, published to the fluid
  std::vector<std::uint8_t> cut;      // 1: a spring at this particle has broken
  std::vector<std::uint8_t> pinned;   // 1: fixed in place (deformables)
  std::size_t size() const { return position.size(); }
};

struct ObjectInfo {
  std::string name;
  ObjectMotion motion = ObjectMotion::Rigid;
  std::size_t firstParticle = 0;
  std::size_t particleCount = 0;
  double mass = 0.0;              // kg (kinematic: of its particles, for reports)
  Vec3 centreOfMass{0, 0, 0};     // m
  Vec3 velocity{0, 0, 0};         // of the centre of mass, m/s
  std::size_t springs = 0;        // deformables (xpbd: distance constraints, not bending)
  std::size_t brokenSprings = 0;  // deformables, including those cut at the start
  // A liquid-filled deformable that keeps its volume (WorldSettings::liquidFilled): the volume
  // its outer particles enclose over the shape's; 0 for any other object.
  double volumeRatio = 0.0;
  // The other objects' contact push on it, and the static particles' on a body that moves,
  // averaged over the last step (N): what a clamp squeezing a vessel feels. A kinematic object
  // feels the other objects' too, though it does not move for it.
  Vec3 contactForce{0, 0, 0};
  Vec3 startCentre{0, 0, 0};  // the centre of mass as built: steer's offsets are from here
};

// What the world's next step reads and its reports show, for a saved simulation state: the
// particles' motion, the rigid bodies', the broken springs and bending triples, the kinematic
// paths as steered. Everything else is fixed when the world is built from its scene.
struct WorldState {
  double time = 0.0;
  std::vector<double> position, velocity;  // x, y, z per particle
  std::vector<double> contactForce;        // x, y, z per object
  std::vector<std::uint8_t> cut;           // per particle
  // Per rigid body: centre of mass, velocity, orientation (w, x, y, z), body angular velocity.
  std::vector<double> bodies;
  std::vector<std::uint8_t> springBroken;    // every network's springs, in order
  std::vector<std::uint8_t> bendingBroken;   // every XPBD network's triples, in order
  std::vector<std::uint64_t> pathKeyCounts;  // per kinematic path
  std::vector<KeyframeDesc> pathKeys;        // their keyframes, one path after another
};

class ObjectWorld {
 public:
  // Samples every object. Throws InputError naming settings.sourceName and the key
  // ("objects[2].shape.radius: ...") when an object cannot be built.
  ObjectWorld(const std::vector<ObjectDesc>& objects, const WorldSettings& settings);
  ~ObjectWorld();
  ObjectWorld(ObjectWorld&&) noexcept;
  ObjectWorld& operator=(ObjectWorld&&) noexcept;

  std::size_t objectCount() const;
  const ParticleState& particles() const;
  ObjectInfo info(std::size_t object) const;
  // The object's surface for drawing, its anchors indices into particles().
  const DrawnSurface& drawnSurface(std::size_t object) const;
  // ObjectInfo::contactForce alone, without summing the object's particles.
  Vec3 contactForce(std::size_t object) const;
  double time() const;
  const PeriodicSpace& periodicSpace() const;

  // Advances by dt. `externalForce` holds, per particle index, a force (N) acting throughout
  // the step (the fluid's contact forces); empty means none. Substeps internally as the
  // springs, masses and contacts require (`stableSubstep`), and no fewer times than any XPBD
  // deformable's `substeps`; kinematic objects follow their keyframes; pinned particles stay.
  // Then a rigid body or a deformable without pinned particles whose centre of mass has left the
  // domain along a periodic axis moves, whole, by a period (WorldSettings::periodic).
  void step(double dt, const std::vector<Vec3>& externalForce);

  // The largest internal step the explicit integration is stable with, for the stiffest
  // spring or contact on the lightest particle. XPBD deformables' constraints do not bound it.
  double stableSubstep() const;

  // Whether p lies in the interior of object `object` as built (its initial shape: box,
  // sphere, capsule, capped tube, closed mesh), at least `margin` inside its particles.
  // False for shapes that enclose nothing (an open tube, a solid body's own volume counts).
  bool interiorContains(std::size_t object, Vec3 p, float margin) const;
  bool enclosesVolume(std::size_t object) const;
  WorldState state() const;
  // Puts back a state of a world built from the same scene, and publishes it as after a step.
  // Throws std::invalid_argument when its sizes are not this world's.
  void restore(const WorldState& state);

  // See KinematicPath::steer. Throws std::invalid_argument unless `object` is kinematic.
  void steer(std::size_t object, Vec3 offset, double arriveIn);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sph::objects
