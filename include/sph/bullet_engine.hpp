// A Bullet world (Coumans, Bullet Physics SDK) as the fluid's object engine: its rigid bodies
// sampled into surface particles, its soft bodies' nodes taken as particles, coupled to the
// fluid through an ObjectExchange (sph/object_exchange.hpp), the fluid's forces applied to them
// at every Bullet substep. Rigid shapes: boxes, spheres, capsules and convex hulls; soft bodies:
// closed balls, ropes and cloths, which can tear. Built where Bullet is (libbullet-dev; the
// CMake target sph::bullet). Bullet stays behind this header: its own headers and precision are not
// the caller's concern.
//
//   sph::BulletEngine engine({spacing, gravity});
//   engine.addBox({0.07, 0.04, 0.05}, {0.1, 0.2, 0.08}, 500.0);
//   sim.attachObjectEngine(engine.exchange());       // publishes the bodies
//   while (...) { sim.step(); engine.step(); }      // or engine.step() in a thread of its own
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "sph/object_exchange.hpp"
#include "sph/scene.hpp"

namespace sph {

class Simulation;

class BulletEngine {
 public:
  using Vec3d = std::array<double, 3>;
  struct Settings {
    double spacing = 0.01;  // of the surface particles, m: the fluid's spacing
    Vec3d gravity{0.0, -9.81, 0.0};
    double longestSubstep = 1e-3;  // s: a step of the fluid's is cut into Bullet substeps
    int leastSubsteps = 1;         // ... and into at least this many (2: Bullet at twice the
                                   // fluid's rate, when step() follows every fluid step)
    // step() hands the world's step to a thread of the engine's own and returns at once; the
    // fluid's next step waits for its publication where it reads the objects (after its density
    // pass, with contact coupling), so the two overlap and the results are those of stepping
    // one after the other.
    bool ownThread = false;
  };
  explicit BulletEngine(const Settings& settings);
  // The bodies of a scene whose object_engine.type is "bullet", in its objects' order: rigid
  // boxes, spheres, capsules along y and meshes (as their convex hull), and deformable spheres
  // as soft balls; its tanks and box walls as fixed boxes for them to collide with. Throws
  // sph::InputError naming the object and key for what Bullet cannot take.
  static std::unique_ptr<BulletEngine> forScene(const Scene& scene);
  // Attaches the bodies to `sim` (Simulation::attachObjectEngine) and gives each closed soft
  // ball the fluid that starts inside it (Simulation::containFluid), as the built-in engine's
  // vessels hold theirs.
  void attachTo(Simulation& sim);
  ~BulletEngine();
  BulletEngine(const BulletEngine&) = delete;
  BulletEngine& operator=(const BulletEngine&) = delete;

  // A free rigid body of `density` (kg/m³) centred at `centre` (m), at rest; returns its object
  // id (0, 1, ... in the order added). Its surface particles lie on a lattice of `spacing`, half
  // a spacing inside its faces, as the fluid's particles fill their cells.
  int addBox(const Vec3d& halfExtents, const Vec3d& centre, double density);
  int addSphere(double radius, const Vec3d& centre, double density);
  // A capsule along y: a cylinder `length` long between two hemispheres of `radius`.
  int addCapsule(double radius, double length, const Vec3d& centre, double density);
  // The convex hull of `vertices` (m, in a frame whose origin is put at `origin`); its centre of
  // mass is the hull's centroid, its volume exact, its inertia Bullet's (its bounding box's).
  int addConvexHull(const std::vector<Vec3d>& vertices, const Vec3d& origin, double density);
  // Soft bodies (Bullet's btSoftBody, position-based): their nodes, about a spacing apart, are
  // their particles, each pushed by the fluid. Ids continue the rigid bodies' sequence.
  struct SoftMaterial {
    double stiffness = 0.9;         // of the links, (0, 1] (Bullet's linear stiffness)
    double bendingStiffness = 0.0;  // of links across two links, [0, 1]; 0: none
    double pressure = 0.0;          // a closed ball's pressure coefficient (Bullet's kPR)
    double volumeStiffness = 0.0;   // how hard a closed ball keeps its volume (Bullet's kVC)
    double damping = 0.0;           // of the nodes' velocity, [0, 1] (not momentum-conserving)
    double breakingStrain = 0.0;    // > 0: a link stretched past (1 + this) × its rest length
                                    // tears (with no pressure or volume stiffness)
    int iterations = 8;             // of Bullet's position solve, a substep
  };
  // A closed ball, its nodes those of an icosahedron subdivided until no edge is longer than a
  // spacing; `mass` (kg) shared by them.
  int addSoftBall(double radius, const Vec3d& centre, double mass, const SoftMaterial& material);
  // A rope from `from` to `to`, its nodes at most a spacing apart; `pinned`: 1 holds its first
  // node in place, 2 its last, 3 both (a pinned node takes no force and no mass).
  int addRope(const Vec3d& from, const Vec3d& to, double mass, const SoftMaterial& material,
              unsigned pinned = 0);
  // A cloth over the parallelogram corner + s·edgeU + t·edgeV; `pinned`: 1, 2, 4, 8 hold its
  // corners at s, t = (0, 0), (1, 0), (0, 1), (1, 1).
  int addCloth(const Vec3d& corner, const Vec3d& edgeU, const Vec3d& edgeV, double mass,
               const SoftMaterial& material, unsigned pinned = 0);
  // A body's velocity (m/s) and a rigid body's spin (rad/s) from now on.
  void setVelocity(int id, const Vec3d& velocity, const Vec3d& spin = {0, 0, 0});
  // Pins a soft body's nodes inside `box` where they are: no force moves them.
  void pinNodes(int id, const AxisBox& box);
  // A fixed box the bodies collide with (a tank's floor and walls); the fluid does not see it.
  void addStaticBox(const Vec3d& halfExtents, const Vec3d& centre);

  // The exchange, made and published at the first call: add every body before it.
  std::shared_ptr<ObjectExchange> exchange();
  // Takes the fluid's mean forces since the last step, applies them (and their torques) at
  // every substep while Bullet advances the world over the time they span, and publishes the
  // bodies where they now are. Does nothing while the fluid has not stepped.
  void step();
  // Until the step handed to the engine's thread is done (at once without one); rethrows what
  // that step threw. body() and time() wait first.
  void wait() const;

  struct Body {
    Vec3d centre{0, 0, 0};    // m: of mass (a soft body's free nodes)
    Vec3d velocity{0, 0, 0};  // m/s: of the centre of mass
    Vec3d spin{0, 0, 0};      // rad/s; 0 for a soft body
    double mass = 0.0;        // kg (a soft body's free nodes)
    std::size_t particles = 0;
    bool soft = false;
    std::size_t links = 0;      // a soft body's links left
    std::size_t tornLinks = 0;  // a soft body's links torn so far
  };
  Body body(int id) const;
  std::size_t bodyCount() const;
  double time() const;  // s of the world

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sph
