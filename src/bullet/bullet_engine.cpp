#include "sph/bullet_engine.hpp"

#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <LinearMath/btConvexHullComputer.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "soft_bodies.hpp"
#include "sph/core/constants.hpp"
#include "sph/simulation.hpp"

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

// Lattice points of spacing `d` whose depth under the surface, given as a signed distance with
// its outward normal (negative inside), lies in [d/2, 3d/2): the outer spacing, half a spacing
// in, as for a box.
template <class SignedDistance>
Sampling sampleBySignedDistance(const btVector3& low, const btVector3& high, double d,
                                SignedDistance signedDistance) {
  Sampling s;
  int n[3];
  for (int a = 0; a < 3; ++a) n[a] = int(std::ceil((high[a] - low[a]) / d)) + 1;
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k) {
        const btVector3 x(btScalar(low[0] + (i + 0.5) * d), btScalar(low[1] + (j + 0.5) * d),
                          btScalar(low[2] + (k + 0.5) * d));
        btVector3 normal;
        const double depth = -signedDistance(x, normal);
        if (depth < 0.5 * d || depth >= 1.5 * d) continue;
        s.offset.push_back(x);
        s.normal.push_back(normal);
      }
  return s;
}

Sampling sampleCapsule(double r, double length, double d) {
  const double half = 0.5 * length;
  const btVector3 corner(btScalar(r), btScalar(r + half), btScalar(r));
  return sampleBySignedDistance(-corner, corner, d, [&](const btVector3& x, btVector3& normal) {
    const double y = std::clamp(double(x.y()), -half, half);
    const btVector3 fromAxis = x - btVector3(0, btScalar(y), 0);
    const double distance = fromAxis.length();
    normal = distance > 0 ? fromAxis / btScalar(distance) : btVector3(1, 0, 0);
    return distance - r;
  });
}

// A convex polytope from its vertices: its outward face planes (n, with w the offset: n·x + w
// is the signed distance), its volume and centroid.
struct Polytope {
  btAlignedObjectArray<btVector3> planes;
  double volume = 0.0;
  btVector3 centroid{0, 0, 0};
};

Polytope polytopeOf(const std::vector<BulletEngine::Vec3d>& vertices) {
  std::vector<btVector3> points;
  for (const auto& v : vertices) points.push_back(toBt(v));
  btConvexHullComputer hull;
  if (points.size() >= 4)
    hull.compute(&points[0].x(), int(sizeof(btVector3)), int(points.size()), 0, 0);
  Polytope p;
  btVector3 inside(0, 0, 0);
  for (int k = 0; k < hull.vertices.size(); ++k) inside += hull.vertices[k];
  if (hull.vertices.size() > 0) inside /= btScalar(hull.vertices.size());
  // Each face, its vertices counter-clockwise seen from outside, fanned into tetrahedra with a
  // point inside.
  btVector3 moment(0, 0, 0);
  for (int f = 0; f < hull.faces.size(); ++f) {
    std::vector<btVector3> face;
    const btConvexHullComputer::Edge* start = &hull.edges[hull.faces[f]];
    const btConvexHullComputer::Edge* e = start;
    do {
      face.push_back(hull.vertices[e->getSourceVertex()]);
      e = e->getNextEdgeOfFace();
    } while (e != start);
    btVector3 n(0, 0, 0);
    for (std::size_t k = 1; k + 1 < face.size() && n.length2() == 0; ++k) {
      const btVector3 c = (face[k] - face[0]).cross(face[k + 1] - face[0]);
      if (c.length2() > 0) n = c.normalized();
    }
    if (n.length2() == 0) continue;
    btVector3 plane = n;
    plane[3] = -n.dot(face[0]);
    p.planes.push_back(plane);
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      const btVector3 a = face[0] - inside, b = face[k] - inside, c = face[k + 1] - inside;
      const double v = double(a.dot(b.cross(c))) / 6.0;
      p.volume += v;
      moment += (inside + face[0] + face[k] + face[k + 1]) * btScalar(0.25 * v);
    }
  }
  if (!(p.volume > 0.0) || p.planes.size() < 4)
    throw std::invalid_argument("BulletEngine: the vertices span no volume");
  p.centroid = moment / btScalar(p.volume);
  return p;
}

Sampling sampleHull(const Polytope& p, const std::vector<BulletEngine::Vec3d>& vertices, double d) {
  btVector3 low(1e30f, 1e30f, 1e30f), high(-1e30f, -1e30f, -1e30f);
  for (const auto& v : vertices) {
    low.setMin(toBt(v) - p.centroid);
    high.setMax(toBt(v) - p.centroid);
  }
  return sampleBySignedDistance(low, high, d, [&](const btVector3& x, btVector3& normal) {
    double largest = -1e30;
    for (int f = 0; f < p.planes.size(); ++f) {
      const btVector3& plane = p.planes[f];
      const btVector3 n(plane.x(), plane.y(), plane.z());
      const double distance = double(n.dot(x + p.centroid) + plane[3]);
      if (distance > largest) largest = distance, normal = n;
    }
    return largest;
  });
}

}  // namespace

struct BulletEngine::Impl {
  Settings settings;
  btSoftBodyRigidBodyCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btSoftRigidDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btRigidBody>> statics;

  struct Free {
    std::unique_ptr<btRigidBody> body;
    Sampling sampling;
    std::uint32_t firstHandle = 0;
    double mass = 0.0;
  };
  struct Soft {
    std::unique_ptr<btSoftBody> body;
    std::uint32_t firstHandle = 0;
    double breakingStrain = 0.0;
    std::vector<std::uint8_t> cut;  // by node: next to a torn link
    std::size_t torn = 0;
    double ballRadius = 0.0;  // a closed ball's, at the start; 0: a rope or a cloth
    btVector3 ballCentre{0, 0, 0};
  };
  std::vector<Free> bodies;
  std::vector<Soft> softs;
  struct Entry {
    bool soft = false;
    std::size_t index = 0;  // in bodies or softs
  };
  std::vector<Entry> objects;  // by object id
  std::uint32_t handleCount = 0;
  std::shared_ptr<ObjectExchange> exchange;
  std::vector<Vec3> force;  // by handle, the last take
  double time = 0.0;

  explicit Impl(const Settings& s) : settings(s) {
    world.setGravity(toBt(s.gravity));
    btSoftBodyWorldInfo& info = world.getWorldInfo();
    info.m_gravity = toBt(s.gravity);
    info.air_density = 0;  // the fluid is the only medium
    info.m_sparsesdf.Initialize();
    // A soft body's nodes integrate their force once, at the first substep, and clear it; the
    // fluid's force is held over the whole step, so it is put back before every substep.
    world.setInternalTickCallback(
        [](btDynamicsWorld* w, btScalar) {
          static_cast<Impl*>(w->getWorldUserInfo())->pushNodes();
        },
        this, true);
  }
  ~Impl() {
    if (worker.joinable()) {
      {
        std::lock_guard<std::mutex> lock(workMutex);
        stopping = true;
      }
      workChanged.notify_all();
      worker.join();
    }
    for (Soft& f : softs) world.removeSoftBody(f.body.get());
    for (Free& f : bodies) world.removeRigidBody(f.body.get());
    for (auto& b : statics) world.removeRigidBody(b.get());
  }

  void checkAddable() const {
    if (exchange) throw std::logic_error("BulletEngine: a body added after exchange()");
  }

  int add(std::unique_ptr<btCollisionShape> shape, Sampling sampling, const Vec3d& centre,
          double density, double volume) {
    checkAddable();
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
    f.firstHandle = handleCount;
    f.mass = mass;
    handleCount += std::uint32_t(f.sampling.offset.size());
    objects.push_back({false, bodies.size()});
    bodies.push_back(std::move(f));
    shapes.push_back(std::move(shape));
    return int(objects.size()) - 1;
  }

  int addSoft(std::unique_ptr<btSoftBody> body, const SoftMaterial& material) {
    bullet::applyMaterial(*body, material, settings.spacing);
    body->setActivationState(DISABLE_DEACTIVATION);
    world.addSoftBody(body.get());
    Soft f;
    f.firstHandle = handleCount;
    f.breakingStrain = material.breakingStrain;
    f.cut.assign(std::size_t(body->m_nodes.size()), 0);
    handleCount += std::uint32_t(body->m_nodes.size());
    f.body = std::move(body);
    objects.push_back({true, softs.size()});
    softs.push_back(std::move(f));
    return int(objects.size()) - 1;
  }

  // The world over `span` under the forces taken, then published.
  void advance(double span) {
    for (Free& f : bodies) {
      btRigidBody& body = *f.body;
      const btTransform& t = body.getWorldTransform();
      btVector3 total(0, 0, 0), torque(0, 0, 0);
      for (std::size_t k = 0; k < f.sampling.offset.size(); ++k) {
        const Vec3& g = force[f.firstHandle + k];
        const btVector3 fk(g.x, g.y, g.z);
        total += fk;
        torque += (t.getBasis() * f.sampling.offset[k]).cross(fk);
      }
      // Held over the whole step: Bullet clears them after its last substep.
      body.applyCentralForce(total);
      body.applyTorque(torque);
    }
    const int substeps =
        std::max(settings.leastSubsteps, int(std::ceil(span / settings.longestSubstep - 1e-9)));
    world.stepSimulation(btScalar(span), substeps, btScalar(span / substeps));
    for (Soft& f : softs)
      f.torn += bullet::tearOverstretchedLinks(*f.body, f.breakingStrain, f.cut);
    time += span;
    publish();
  }

  // Settings::ownThread: steps handed over by step(), one at a time.
  std::thread worker;
  std::mutex workMutex;
  std::condition_variable workChanged;
  bool pending = false, stopping = false;
  double pendingSpan = 0.0;
  std::exception_ptr error;

  void work() {
    std::unique_lock<std::mutex> lock(workMutex);
    for (;;) {
      workChanged.wait(lock, [&] { return pending || stopping; });
      if (stopping) return;
      lock.unlock();
      try {
        advance(pendingSpan);
      } catch (...) {
        error = std::current_exception();
        exchange->announce(false);  // the fluid waits for nothing
      }
      lock.lock();
      pending = false;
      workChanged.notify_all();
    }
  }

  void pushNodes() {
    for (Soft& f : softs) {
      btSoftBody& body = *f.body;
      for (int k = 0; k < body.m_nodes.size(); ++k) {
        const Vec3& g = force[f.firstHandle + std::uint32_t(k)];
        body.addForce(btVector3(g.x, g.y, g.z), k);  // nothing on a pinned node
      }
    }
  }

  void publish() {
    ObjectSurface& s = exchange->back();
    s.clear();
    const float radius = float(0.5 * settings.spacing);
    for (std::size_t id = 0; id < objects.size(); ++id) {
      if (objects[id].soft) {
        const Soft& f = softs[objects[id].index];
        const btSoftBody& body = *f.body;
        for (int k = 0; k < body.m_nodes.size(); ++k) {
          const btSoftBody::Node& node = body.m_nodes[k];
          // A rope's nodes have no normal: the contact pushes along the line of centres anyway.
          const btVector3 n = node.m_n.length2() > 0 ? node.m_n.normalized() : btVector3(0, 0, 0);
          s.add(Vec3{float(node.m_x.x()), float(node.m_x.y()), float(node.m_x.z())},
                Vec3{float(node.m_v.x()), float(node.m_v.y()), float(node.m_v.z())}, radius,
                Vec3{float(n.x()), float(n.y()), float(n.z())}, f.firstHandle + std::uint32_t(k),
                std::int32_t(id), f.cut[std::size_t(k)] != 0);
        }
        continue;
      }
      const Free& f = bodies[objects[id].index];
      const btRigidBody& body = *f.body;
      const btTransform& t = body.getWorldTransform();
      const btVector3 v = body.getLinearVelocity(), w = body.getAngularVelocity();
      for (std::size_t k = 0; k < f.sampling.offset.size(); ++k) {
        const btVector3 r = t.getBasis() * f.sampling.offset[k];
        const btVector3 x = t.getOrigin() + r, u = v + w.cross(r);
        const btVector3 n = t.getBasis() * f.sampling.normal[k];
        s.add(Vec3{float(x.x()), float(x.y()), float(x.z())},
              Vec3{float(u.x()), float(u.y()), float(u.z())}, radius,
              Vec3{float(n.x()), float(n.y()), float(n.z())}, f.firstHandle + std::uint32_t(k),
              std::int32_t(id), false);
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
  if (settings.leastSubsteps < 1 || settings.leastSubsteps > 1000)
    throw std::invalid_argument("BulletEngine: expected at least 1 substep and at most 1000");
}

BulletEngine::~BulletEngine() = default;

int BulletEngine::addBox(const Vec3d& halfExtents, const Vec3d& centre, double density) {
  const btVector3 half = toBt(halfExtents);
  return impl_->add(std::make_unique<btBoxShape>(half), sampleBox(half, impl_->settings.spacing),
                    centre, density, 8.0 * halfExtents[0] * halfExtents[1] * halfExtents[2]);
}

int BulletEngine::addSphere(double radius, const Vec3d& centre, double density) {
  return impl_->add(std::make_unique<btSphereShape>(btScalar(radius)),
                    sampleSphere(radius, impl_->settings.spacing), centre, density,
                    4.0 / 3.0 * kPi * radius * radius * radius);
}

int BulletEngine::addCapsule(double radius, double length, const Vec3d& centre, double density) {
  return impl_->add(std::make_unique<btCapsuleShape>(btScalar(radius), btScalar(length)),
                    sampleCapsule(radius, length, impl_->settings.spacing), centre, density,
                    kPi * radius * radius * (length + 4.0 / 3.0 * radius));
}

int BulletEngine::addConvexHull(const std::vector<Vec3d>& vertices, const Vec3d& origin,
                                double density) {
  const Polytope p = polytopeOf(vertices);
  auto shape = std::make_unique<btConvexHullShape>();
  for (const auto& v : vertices) shape->addPoint(toBt(v) - p.centroid, false);
  shape->recalcLocalAabb();
  shape->setMargin(btScalar(1e-3));  // Bullet's 4 cm default would hold it off the floor
  const btVector3 centre = toBt(origin) + p.centroid;
  return impl_->add(std::move(shape), sampleHull(p, vertices, impl_->settings.spacing),
                    fromBt(centre), density, p.volume);
}

int BulletEngine::addSoftBall(double radius, const Vec3d& centre, double mass,
                              const SoftMaterial& material) {
  impl_->checkAddable();
  if (!(mass > 0.0)) throw std::invalid_argument("BulletEngine: expected a mass > 0");
  const int id = impl_->addSoft(bullet::makeSoftBall(impl_->world.getWorldInfo(), radius,
                                                     toBt(centre), mass, impl_->settings.spacing),
                                material);
  Impl::Soft& ball = impl_->softs.back();
  ball.ballRadius = radius;
  ball.ballCentre = toBt(centre);
  return id;
}

int BulletEngine::addRope(const Vec3d& from, const Vec3d& to, double mass,
                          const SoftMaterial& material, unsigned pinned) {
  impl_->checkAddable();
  if (!(mass > 0.0)) throw std::invalid_argument("BulletEngine: expected a mass > 0");
  if (!(toBt(from).distance(toBt(to)) > 0))
    throw std::invalid_argument("BulletEngine: a rope's ends must differ");
  return impl_->addSoft(bullet::makeRope(impl_->world.getWorldInfo(), toBt(from), toBt(to), mass,
                                         impl_->settings.spacing, pinned),
                        material);
}

int BulletEngine::addCloth(const Vec3d& corner, const Vec3d& edgeU, const Vec3d& edgeV, double mass,
                           const SoftMaterial& material, unsigned pinned) {
  impl_->checkAddable();
  if (!(mass > 0.0)) throw std::invalid_argument("BulletEngine: expected a mass > 0");
  if (!(toBt(edgeU).cross(toBt(edgeV)).length() > 0))
    throw std::invalid_argument("BulletEngine: a cloth's edges must span an area");
  return impl_->addSoft(bullet::makeCloth(impl_->world.getWorldInfo(), toBt(corner), toBt(edgeU),
                                          toBt(edgeV), mass, impl_->settings.spacing, pinned),
                        material);
}

void BulletEngine::setVelocity(int id, const Vec3d& velocity, const Vec3d& spin) {
  wait();
  if (id < 0 || std::size_t(id) >= impl_->objects.size())
    throw std::out_of_range("BulletEngine::setVelocity: no body " + std::to_string(id));
  const Impl::Entry entry = impl_->objects[std::size_t(id)];
  if (entry.soft) {
    impl_->softs[entry.index].body->setVelocity(toBt(velocity));
  } else {
    btRigidBody& body = *impl_->bodies[entry.index].body;
    body.setLinearVelocity(toBt(velocity));
    body.setAngularVelocity(toBt(spin));
  }
}

void BulletEngine::pinNodes(int id, const AxisBox& box) {
  if (id < 0 || std::size_t(id) >= impl_->objects.size() || !impl_->objects[std::size_t(id)].soft)
    throw std::out_of_range("BulletEngine::pinNodes: no soft body " + std::to_string(id));
  btSoftBody& body = *impl_->softs[impl_->objects[std::size_t(id)].index].body;
  for (int k = 0; k < body.m_nodes.size(); ++k) {
    const btVector3& x = body.m_nodes[k].m_x;
    bool inside = true;
    for (int a = 0; a < 3; ++a) inside = inside && x[a] >= box.min[a] && x[a] <= box.max[a];
    if (inside) body.setMass(k, 0);
  }
}

void BulletEngine::attachTo(Simulation& sim) {
  sim.attachObjectEngine(exchange());
  const ParticleFrame fluid = sim.frame(false);
  for (std::size_t id = 0; id < impl_->objects.size(); ++id) {
    if (!impl_->objects[id].soft) continue;
    const Impl::Soft& f = impl_->softs[impl_->objects[id].index];
    if (f.ballRadius <= 0.0) continue;
    std::vector<std::uint32_t> inside;
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      if (fluid.kind[i] != std::uint8_t(ParticleKind::Fluid)) continue;
      const btVector3 x(fluid.position[3 * i], fluid.position[3 * i + 1],
                        fluid.position[3 * i + 2]);
      if (x.distance(f.ballCentre) < f.ballRadius) inside.push_back(fluid.id[i]);
    }
    if (!inside.empty()) sim.containFluid(std::int32_t(id), inside);
  }
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
    if (impl_->objects.empty()) throw std::logic_error("BulletEngine: no body to exchange");
    impl_->exchange = std::make_shared<ObjectExchange>(impl_->handleCount);
    impl_->publish();
    if (impl_->settings.ownThread)
      impl_->worker = std::thread([impl = impl_.get()] { impl->work(); });
  }
  return impl_->exchange;
}

void BulletEngine::step() {
  Impl& s = *impl_;
  if (!s.exchange) throw std::logic_error("BulletEngine::step before exchange()");
  wait();
  // Taken here, in the caller's thread: the fluid's next step deposits the next forces.
  const double span = s.exchange->takeForces(s.force);
  if (span <= 0.0) return;
  if (!s.settings.ownThread) {
    s.advance(span);
    return;
  }
  s.exchange->announce();
  {
    std::lock_guard<std::mutex> lock(s.workMutex);
    s.pendingSpan = span;
    s.pending = true;
  }
  s.workChanged.notify_all();
}

void BulletEngine::wait() const {
  Impl& s = *impl_;
  if (!s.settings.ownThread) return;
  std::unique_lock<std::mutex> lock(s.workMutex);
  s.workChanged.wait(lock, [&] { return !s.pending; });
  if (s.error) std::rethrow_exception(std::exchange(s.error, nullptr));
}

BulletEngine::Body BulletEngine::body(int id) const {
  wait();
  if (id < 0 || std::size_t(id) >= impl_->objects.size())
    throw std::out_of_range("BulletEngine::body: no body " + std::to_string(id));
  const Impl::Entry entry = impl_->objects[std::size_t(id)];
  Body b;
  if (entry.soft) {
    const Impl::Soft& f = impl_->softs[entry.index];
    btVector3 moment(0, 0, 0), momentum(0, 0, 0);
    for (int k = 0; k < f.body->m_nodes.size(); ++k) {
      const btSoftBody::Node& node = f.body->m_nodes[k];
      if (node.m_im <= 0) continue;
      const double m = 1.0 / double(node.m_im);
      b.mass += m;
      moment += node.m_x * btScalar(m);
      momentum += node.m_v * btScalar(m);
    }
    b.centre = fromBt(moment / btScalar(b.mass));
    b.velocity = fromBt(momentum / btScalar(b.mass));
    b.particles = std::size_t(f.body->m_nodes.size());
    b.soft = true;
    b.links = std::size_t(f.body->m_links.size());
    b.tornLinks = f.torn;
    return b;
  }
  const Impl::Free& f = impl_->bodies[entry.index];
  b.centre = fromBt(f.body->getWorldTransform().getOrigin());
  b.velocity = fromBt(f.body->getLinearVelocity());
  b.spin = fromBt(f.body->getAngularVelocity());
  b.mass = f.mass;
  b.particles = f.sampling.offset.size();
  return b;
}

std::size_t BulletEngine::bodyCount() const {
  return impl_->objects.size();
}

double BulletEngine::time() const {
  wait();
  return impl_->time;
}

}  // namespace sph
