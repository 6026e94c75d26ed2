#include "sph/bullet_engine.hpp"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace sph {
namespace {

btVector3 toBt(const BulletEngine::Vec3d& v) {
  return btVector3(btScalar(v[0]), btScalar(v[1]), btScalar(v[2]));
}

BulletEngine::Vec3d fromBt(const btVector3& v) {
  return {double(v.x()), double(v.y()), double(v.z())};
}

// A body's surface particles in its own frame: offsets from its centre and outward normals.
struct Sampling {
  std::vector<btVector3> offset, normal;
};

// The outer layer of a lattice of cells of `d` filling the box, each particle at its cell's
// centre: half a spacing inside the faces.
Sampling sampleBox(const btVector3& half, double d) {
  Sampling s;
  int n[3];
  for (int a = 0; a < 3; ++a) n[a] = std::max(1, int(std::lround(2.0 * half[a] / d)));
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k) {
        const int at[3] = {i, j, k};
        btVector3 normal(0, 0, 0);
        for (int a = 0; a < 3; ++a) {
          if (at[a] == 0) normal[a] -= 1;
          if (at[a] == n[a] - 1) normal[a] += 1;
        }
        if (normal.length2() == 0) continue;  // inside
        btVector3 x;
        for (int a = 0; a < 3; ++a)
          x[a] = btScalar(-half[a] + (at[a] + 0.5) * 2.0 * half[a] / n[a]);
        s.offset.push_back(x);
        s.normal.push_back(normal.normalized());
      }
  return s;
}

// The lattice points of spacing `d` within the sphere's outer spacing: (r - d, r - d/2].
Sampling sampleSphere(double r, double d) {
  Sampling s;
  const int n = int(std::ceil(r / d)) + 1;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int k = -n; k <= n; ++k) {
        const btVector3 x(btScalar((i + 0.5) * d), btScalar((j + 0.5) * d),
                          btScalar((k + 0.5) * d));
        const double length = x.length();
        if (length > r - 0.5 * d || length <= r - 1.5 * d) continue;
        s.offset.push_back(x);
        s.normal.push_back(x / btScalar(length));
      }
  return s;
}

}  // namespace

struct BulletEngine::Impl {
  Settings settings;
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btRigidBody>> statics;

  struct Free {
    std::unique_ptr<btRigidBody> body;
    Sampling sampling;
    std::uint32_t firstHandle = 0;
    double mass = 0.0;
  };
  std::vector<Free> bodies;
  std::shared_ptr<ObjectExchange> exchange;
  std::vector<Vec3> force;  // by handle, the last take
  double time = 0.0;

  explicit Impl(const Settings& s) : settings(s) { world.setGravity(toBt(s.gravity)); }
  ~Impl() {
    for (Free& f : bodies) world.removeRigidBody(f.body.get());
    for (auto& b : statics) world.removeRigidBody(b.get());
  }

  int add(std::unique_ptr<btCollisionShape> shape, Sampling sampling, const Vec3d& centre,
          double density, double volume) {
    if (exchange) throw std::logic_error("BulletEngine: a body added after exchange()");
    if (!(density > 0.0)) throw std::invalid_argument("BulletEngine: expected a density > 0");
    const double mass = density * volume;
    btVector3 inertia(0, 0, 0);
    shape->calculateLocalInertia(btScalar(mass), inertia);
    btTransform start;
    start.setIdentity();
    start.setOrigin(toBt(centre));
    btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass), nullptr, shape.get(), inertia);
    info.m_startWorldTransform = start;
    auto body = std::make_unique<btRigidBody>(info);
    body->setActivationState(DISABLE_DEACTIVATION);  // the fluid moves it whatever Bullet thinks
    world.addRigidBody(body.get());
    Free f;
    f.body = std::move(body);
    f.sampling = std::move(sampling);
    f.firstHandle = bodies.empty() ? 0
                                   : bodies.back().firstHandle +
                                         std::uint32_t(bodies.back().sampling.offset.size());
    f.mass = mass;
    bodies.push_back(std::move(f));
    shapes.push_back(std::move(shape));
    return int(bodies.size()) - 1;
  }

  std::size_t handles() const {
    return bodies.empty() ? 0 : bodies.back().firstHandle + bodies.back().sampling.offset.size();
  }

  void publish() {
    ObjectSurface& s = exchange->back();
    s.clear();
    const float radius = float(0.5 * settings.spacing);
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const btRigidBody& body = *bodies[b].body;
      const btTransform& t = body.getWorldTransform();
      const btVector3 v = body.getLinearVelocity(), w = body.getAngularVelocity();
      const Sampling& sampling = bodies[b].sampling;
      for (std::size_t k = 0; k < sampling.offset.size(); ++k) {
        const btVector3 r = t.getBasis() * sampling.offset[k];
        const btVector3 x = t.getOrigin() + r, u = v + w.cross(r);
        const btVector3 n = t.getBasis() * sampling.normal[k];
        s.add(Vec3{float(x.x()), float(x.y()), float(x.z())},
              Vec3{float(u.x()), float(u.y()), float(u.z())}, radius,
              Vec3{float(n.x()), float(n.y()), float(n.z())},
              bodies[b].firstHandle + std::uint32_t(k), std::int32_t(b), false);
      }
    }
    s.time = time;
    exchange->publish();
  }
};

BulletEngine::BulletEngine(const Settings& settings) : impl_(std::make_unique<Impl>(settings)) {
  if (!(settings.spacing > 0.0))
    throw std::invalid_argument("BulletEngine: expected a spacing > 0");
  if (!(settings.longestSubstep > 0.0))
    throw std::invalid_argument("BulletEngine: expected a longest substep > 0");
}

BulletEngine::~BulletEngine() = default;

int BulletEngine::addBox(const Vec3d& halfExtents, const Vec3d& centre, double density) {
  const btVector3 half = toBt(halfExtents);
  return impl_->add(std::make_unique<btBoxShape>(half), sampleBox(half, impl_->settings.spacing),
                    centre, density, 8.0 * halfExtents[0] * halfExtents[1] * halfExtents[2]);
}

int BulletEngine::addSphere(double radius, const Vec3d& centre, double density) {
  constexpr double kPi = 3.14159265358979323846;
  return impl_->add(std::make_unique<btSphereShape>(btScalar(radius)),
                    sampleSphere(radius, impl_->settings.spacing), centre, density,
                    4.0 / 3.0 * kPi * radius * radius * radius);
}

void BulletEngine::addStaticBox(const Vec3d& halfExtents, const Vec3d& centre) {
  auto shape = std::make_unique<btBoxShape>(toBt(halfExtents));
  btTransform at;
  at.setIdentity();
  at.setOrigin(toBt(centre));
  btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, shape.get());
  info.m_startWorldTransform = at;
  auto body = std::make_unique<btRigidBody>(info);
  impl_->world.addRigidBody(body.get());
  impl_->statics.push_back(std::move(body));
  impl_->shapes.push_back(std::move(shape));
}

std::shared_ptr<ObjectExchange> BulletEngine::exchange() {
  if (!impl_->exchange) {
    if (impl_->bodies.empty()) throw std::logic_error("BulletEngine: no body to exchange");
    impl_->exchange = std::make_shared<ObjectExchange>(impl_->handles());
    impl_->publish();
  }
  return impl_->exchange;
}

void BulletEngine::step() {
  Impl& s = *impl_;
  if (!s.exchange) throw std::logic_error("BulletEngine::step before exchange()");
  const double span = s.exchange->takeForces(s.force);
  if (span <= 0.0) return;
  for (Impl::Free& f : s.bodies) {
    btRigidBody& body = *f.body;
    const btTransform& t = body.getWorldTransform();
    btVector3 total(0, 0, 0), torque(0, 0, 0);
    for (std::size_t k = 0; k < f.sampling.offset.size(); ++k) {
      const Vec3& g = s.force[f.firstHandle + k];
      const btVector3 fk(g.x, g.y, g.z);
      total += fk;
      torque += (t.getBasis() * f.sampling.offset[k]).cross(fk);
    }
    // Held over the whole step: Bullet clears them after its last substep.
    body.applyCentralForce(total);
    body.applyTorque(torque);
  }
  const int substeps = std::max(1, int(std::ceil(span / s.settings.longestSubstep - 1e-9)));
  s.world.stepSimulation(btScalar(span), substeps, btScalar(span / substeps));
  s.time += span;
  s.publish();
}

BulletEngine::Body BulletEngine::body(int id) const {
  if (id < 0 || std::size_t(id) >= impl_->bodies.size())
    throw std::out_of_range("BulletEngine::body: no body " + std::to_string(id));
  const Impl::Free& f = impl_->bodies[std::size_t(id)];
  Body b;
  b.centre = fromBt(f.body->getWorldTransform().getOrigin());
  b.velocity = fromBt(f.body->getLinearVelocity());
  b.spin = fromBt(f.body->getAngularVelocity());
  b.mass = f.mass;
  b.particles = f.sampling.offset.size();
  return b;
}

std::size_t BulletEngine::bodyCount() const {
  return impl_->bodies.size();
}

double BulletEngine::time() const {
  return impl_->time;
}

}  // namespace sph
