#include "objects/object_world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "objects/axis_box.hpp"
#include "objects/contact_constraints.hpp"
#include "objects/kinematic_path.hpp"
#include "objects/math3d.hpp"
#include "objects/object_contacts.hpp"
#include "objects/point_grid.hpp"
#include "objects/rigid_body.hpp"
#include "objects/shape_sampling.hpp"
#include "objects/springs.hpp"
#include "objects/volume_constraint.hpp"
#include "objects/xpbd.hpp"
#include "sph/core/constants.hpp"
#include "sph/core/time_step.hpp"
#include "sph/error.hpp"

namespace sph::objects {

namespace {

// Substeps resolve the fastest oscillation with h = kStepPerOmega / ω, about 1/21 of its
// period. Symplectic Euler alone is stable to ω h < 2, with critical damping on the same spring
// to ω h < 0.83; a particle held by many springs (up to 18 at reach 1.5) oscillates up to ~2.5×
// faster than one spring on its own, hence the margin.
constexpr double kStepPerOmega = 0.3;
// Explicit damping c on a mass m is stable for c h / m < 2; several contacts or springs add up.
constexpr double kStepPerDampingRate = 0.25;
// No particle moves more than this fraction of its radius per substep, so nothing tunnels
// (Meteer 2011, §8.3).
constexpr double kMaxTravelPerRadius = 0.25;
// Default spring stiffness: the object's weight hung on one spring strains it by 1 %.
constexpr double kDefaultWeightStrain = 0.01;
constexpr double kStandardGravity = 9.80665;  // for the default stiffness in zero gravity
// A diverging run must not turn one step into an endless loop of substeps.
constexpr double kMaxSubsteps = 1e6;
// Bending triples join nearest neighbours: those closer than this × spacing, a lattice's edges
// (1) and face diagonals (√2) but not the next shell (2).
constexpr double kNearestShell = 1.5;

void requireNonNegative(double value, const std::string& where, const std::string& key) {
  if (!(value >= 0.0) || !std::isfinite(value))
    throw InputError(where + "." + key + ": expected a number ≥ 0, got " + formatNumber(value));
}

// The object's spacing (its own, else the fluid's), after checking it and the density.
double checkedSpacing(const ObjectDesc& desc, double defaultSpacing, const std::string& where) {
  if (desc.spacing < 0.0 || !std::isfinite(desc.spacing))
    throw InputError(where + ".spacing: expected a positive number, got " +
                     formatNumber(desc.spacing));
  const double spacing = desc.spacing > 0.0 ? desc.spacing : defaultSpacing;
  if (!(spacing > 0.0))
    throw InputError(where + ".spacing: expected a positive number (no fluid spacing to default " +
                     "to), got " + formatNumber(desc.spacing));
  if (!(desc.density > 0.0) || !std::isfinite(desc.density))
    throw InputError(where + ".density: expected a positive number, got " +
                     formatNumber(desc.density));

  return spacing;
}

}  // namespace

struct ObjectWorld::Impl {
  struct Object {
    std::string name;
    ObjectMotion motion = ObjectMotion::Rigid;
    std::size_t first = 0, count = 0;
    BuiltShape shape;
    DrawnSurface drawn;    // anchors: particle indices of the world
    std::size_t body = 0;  // index into rigid, networks or paths, by motion
    DVec3 initialCentre;   // centre of mass at the start
  };

  WorldSettings settings;
  DVec3 gravity;
  double time = 0.0;

  // Per particle (N each), written by the substeps; published as floats after each step.
  std::vector<DVec3> position, velocity;
  std::vector<DVec3> initialPosition, restNormal;  // the pose as sampled
  std::vector<DVec3> force;                        // scratch, N
  std::vector<DVec3> contactImpulse;               // by object, over the step so far, N s
  std::vector<DVec3> contactForce;                 // by object, the last step's mean, N
  std::vector<std::uint8_t> movable;               // 0: kinematic or pinned
  std::vector<ContactRole> role;                   // how each meets other objects
  std::vector<double> inverseMass;                 // 1/kg of the Projected, 0 for the rest
  ParticleState published;

  std::vector<Object> objects;
  std::vector<RigidBody> rigid;
  std::vector<SpringNetwork> networks;
  std::vector<DeformableModel> models;    // per network
  std::vector<XpbdConstraints> xpbd;      // per network; unused under the springs model
  std::vector<VolumeConstraint> volumes;  // of the liquid-filled deformables
  std::vector<KinematicPath> paths;

  // Stability data, fixed at build time.
  bool contactsPossible = false;
  double shortestSpringStep = std::numeric_limits<double>::infinity();  // 1/ω, s
  double fastestSpringDamping = 0.0;                                    // c / m_reduced, 1/s
  // What a contact force pushes against: a whole rigid body (its mass as felt at its outermost
  // particle), one free particle of a spring network; and one free particle of an XPBD
  // deformable, which meets pushed particles by forces too.
  double lightestPushedMass = std::numeric_limits<double>::infinity();
  double lightestProjectedMass = std::numeric_limits<double>::infinity();
  int xpbdSubsteps = 0;  // the most any XPBD deformable asks for per step
  float minRadius = std::numeric_limits<float>::infinity(), maxRadius = 0.0f;
  ContactSearch contactSearch;
  ContactConstraints contactConstraints;
  std::vector<DVec3> statics;  // settings.staticParticles
  PointGrid staticGrid;

  void addObject(const ObjectDesc& desc, std::size_t index);
  // Appends the samples as particles; returns their centre.
  DVec3 appendParticles(const ShapeSamples& samples, const ObjectDesc& desc, std::size_t index,
                        double particleMass, float radius);
  void makeDeformable(const ObjectDesc& desc, Object& object, const std::string& where);
  void placeKinematic(const Object& object);
  void substep(double h, const std::vector<Vec3>& externalForce);
  ContactParticles contactParticles() const;
  StaticParticles staticParticles() const;
  void keepVolumes();
  void projectXpbd(double h);
  void addContactImpulses(double h);
  void integrateDeformable(const SpringNetwork& net, double h);
  void integrateRigid(const Object& object, RigidBody& body, double h);
  void publish();
  void wrapAcrossPeriodicFaces();
  double stableSubstep() const;
  double fastestInRegion() const;
  void findContactCandidates(double dt);
};

// The volume the described shape encloses, m³.
double enclosedVolume(const ShapeDesc& shape, const BuiltShape& built) {
  const double r = shape.radius;
  switch (shape.kind) {
    case ShapeKind::Box:
      return 8.0 * shape.halfExtents[0] * shape.halfExtents[1] * shape.halfExtents[2];
    case ShapeKind::Sphere:
      return 4.0 / 3.0 * kPi * r * r * r;
    case ShapeKind::Capsule:
      return kPi * r * r * shape.length + 4.0 / 3.0 * kPi * r * r * r;
    case ShapeKind::Tube:
      return kPi * r * r * shape.length;
    case ShapeKind::Mesh:
      return std::abs(signedVolume(built.mesh));
  }
  return 0.0;
}

void ObjectWorld::Impl::addObject(const ObjectDesc& desc, std::size_t index) {
  const std::string where = (settings.sourceName.empty() ? "" : settings.sourceName + ": ") +
                            "objects[" + std::to_string(index) + "]";
  const double spacing = checkedSpacing(desc, double(settings.defaultSpacing), where);

  Object object;
  object.name = desc.name;
  object.motion = desc.motion;
  object.first = position.size();
  // A solid body's particles are spheres that fill its shape, as the fluid's fill a block and
  // the walls' lie outside the tank: the fluid and other bodies then meet it at its described
  // surface, and it floats at the draft its volume gives. A deformable is described by its
  // particle layer (a vessel's wall).
  const double inset = desc.motion == ObjectMotion::Deformable ? 0.0 : 0.5 * spacing;
  const ShapeSamples samples =
      sampleShape(desc.shape, spacing, inset, where, settings.sceneFolder, object.shape);
  object.count = samples.position.size();
  object.drawn = objects::drawnSurface(desc.shape, samples, object.shape, spacing);
  for (auto& anchor : object.drawn.anchor)
    for (std::uint32_t& k : anchor) k += std::uint32_t(object.first);

  // Each particle stands for a cube of edge `spacing`, a surface layer being `spacing` thick;
  // but a rigid body sampled on its surface is a solid body: its particles share the mass of
  // its whole volume (the inertia is then that of a shell, up to 5/3 of the solid's).
  double particleMass = desc.density * spacing * spacing * spacing;
  if (desc.motion == ObjectMotion::Rigid && object.shape.enclosesVolume && object.count > 0)
    particleMass = desc.density * enclosedVolume(desc.shape, object.shape) / double(object.count);
  const float radius = float(0.5 * spacing);
  object.initialCentre = appendParticles(samples, desc, index, particleMass, radius);
  minRadius = std::min(minRadius, radius);
  maxRadius = std::max(maxRadius, radius);

  switch (desc.motion) {
    case ObjectMotion::Rigid: {
      const std::vector<double> masses(object.count, particleMass);
      const std::vector<DVec3> points(position.begin() + object.first, position.end());
      object.body = rigid.size();
      rigid.emplace_back(points, masses, spacing, toD(desc.velocity), toD(desc.angularVelocity));
      const RigidBody& body = rigid.back();
      for (std::size_t k = 0; k < object.count; ++k)
        velocity[object.first + k] =
            body.velocity() + cross(body.angularVelocity(), body.localPositions()[k]);
      break;
    }
    case ObjectMotion::Deformable:
      makeDeformable(desc, object, where);
      break;
    case ObjectMotion::Kinematic:
      validateKeyframes(desc.keyframes, where);
      object.body = paths.size();
      paths.emplace_back(desc.keyframes);
      placeKinematic(object);
      break;
  }
  const bool projected =
      desc.motion == ObjectMotion::Deformable && desc.deformable.model == DeformableModel::Xpbd;
  if (desc.motion == ObjectMotion::Rigid)
    lightestPushedMass = std::min(lightestPushedMass, rigid[object.body].contactMass());
  for (std::size_t i = object.first; i < object.first + object.count; ++i) {
    role.push_back(!movable[i] ? ContactRole::Fixed
                   : projected ? ContactRole::Projected
                               : ContactRole::Pushed);
    inverseMass.push_back(role.back() == ContactRole::Projected ? 1.0 / particleMass : 0.0);
    if (!movable[i] || desc.motion != ObjectMotion::Deformable) continue;
    double& lightest = projected ? lightestProjectedMass : lightestPushedMass;
    lightest = std::min(lightest, particleMass);
  }
  objects.push_back(std::move(object));
}

DVec3 ObjectWorld::Impl::appendParticles(const ShapeSamples& samples, const ObjectDesc& desc,
                                         std::size_t index, double particleMass, float radius) {
  const bool kinematic = desc.motion == ObjectMotion::Kinematic;
  DVec3 moment{0, 0, 0};
  for (std::size_t k = 0; k < samples.position.size(); ++k) {
    position.push_back(samples.position[k]);
    initialPosition.push_back(samples.position[k]);
    restNormal.push_back(samples.normal[k]);
    velocity.push_back(kinematic ? DVec3{} : toD(desc.velocity));
    movable.push_back(kinematic ? 0 : 1);
    published.mass.push_back(float(particleMass));
    published.radius.push_back(radius);
    published.object.push_back(std::int32_t(index));
    published.surface.push_back(samples.surface[k]);
    published.cut.push_back(0);
    published.pinned.push_back(0);
    moment += samples.position[k];
  }
  return moment / double(samples.position.size());  // the centre of mass: equal masses
}

void ObjectWorld::Impl::makeDeformable(const ObjectDesc& desc, Object& object,
                                       const std::string& where) {
  const DeformableDesc& d = desc.deformable;
  requireNonNegative(d.stiffness, where, "deformable.stiffness");
  requireNonNegative(d.damping, where, "deformable.damping");
  requireNonNegative(d.breakingStrain, where, "deformable.breaking_strain");
  if (!(d.springReach > 1.0 && d.springReach <= DeformableDesc::kMaxSpringReach))
    throw InputError(where + ".deformable.spring_reach: expected a number in (1, " +
                     formatNumber(DeformableDesc::kMaxSpringReach) + "] (× spacing), got " +
                     formatNumber(d.springReach));
  requireNonNegative(d.bendingStiffness, where, "deformable.bending_stiffness");
  if (d.substeps < 1)
    throw InputError(where + ".deformable.substeps: expected an integer ≥ 1, got " +
                     std::to_string(d.substeps));
  const double spacing = object.shape.spacing;
  for (std::size_t i = object.first; i < object.first + object.count; ++i) {
    for (const AxisBox& box : d.pinned)
      if (insideBox(box, position[i])) {
        published.pinned[i] = 1;
        movable[i] = 0;
        velocity[i] = {0, 0, 0};
      }
  }
  SpringNetwork net =
      buildSprings(position, restNormal, object.first, object.count, d.springReach * spacing);
  // A cut is a slit made beforehand: the springs that pass through a cut box start broken, and
  // the particles they joined are torn.
  for (std::size_t s = 0; s < net.springs.size(); ++s) {
    const Spring& spring = net.springs[s];
    for (const AxisBox& box : d.cuts) {
      if (net.broken[s] || !segmentMeetsBox(box, position[spring.a], position[spring.b])) continue;
      net.broken[s] = 1;
      ++net.brokenCount;
      published.cut[spring.a] = published.cut[spring.b] = 1;
    }
  }
  const double particleMass = published.mass[object.first];
  const double objectMass = particleMass * double(object.count);
  const double g = norm(gravity) > 0.0 ? norm(gravity) : kStandardGravity;
  // k · (1 % of the rest spacing) = the object's weight.
  net.stiffness =
      d.stiffness > 0.0 ? d.stiffness : objectMass * g / (kDefaultWeightStrain * spacing);
  // Critical damping of one spring between two particles: c = 2 √(k m_red), m_red = m/2.
  const double reducedMass = 0.5 * particleMass;
  net.damping = d.damping > 0.0 ? d.damping : 2.0 * std::sqrt(net.stiffness * reducedMass);
  net.breakingStrain = d.breakingStrain;
  XpbdConstraints constraints;
  if (d.model == DeformableModel::Xpbd) {
    // Constraints, not forces: their stiffness does not bound the substep.
    constraints = makeXpbdConstraints(net, position, published.mass, published.pinned,
                                      kNearestShell * spacing, d.bendingStiffness, d.substeps);
    breakBendingAcrossTears(net, constraints);  // those across the cuts
    xpbdSubsteps = std::max(xpbdSubsteps, d.substeps);
  } else if (!net.springs.empty()) {
    shortestSpringStep =
        std::min(shortestSpringStep, springTimeStep(reducedMass, net.stiffness, 1.0));
    fastestSpringDamping = std::max(fastestSpringDamping, net.damping / reducedMass);
  }
  object.body = networks.size();
  networks.push_back(std::move(net));
  models.push_back(d.model);
  xpbd.push_back(std::move(constraints));
}

void ObjectWorld::Impl::placeKinematic(const Object& object) {
  const KinematicPose pose = paths[object.body].at(time);
  for (std::size_t i = object.first; i < object.first + object.count; ++i) {
    const DVec3 arm = pose.rotation * (initialPosition[i] - object.initialCentre);
    position[i] = object.initialCentre + pose.offset + arm;
    velocity[i] = pose.velocity + cross(pose.angularVelocity, arm);
  }
}

void ObjectWorld::Impl::integrateDeformable(const SpringNetwork& net, double h) {
  for (std::size_t i = net.first; i < net.first + net.count; ++i) {
    if (published.pinned[i]) continue;
    // Symplectic Euler: the new velocity moves the particle.
    velocity[i] += (force[i] / double(published.mass[i]) + gravity) * h;
    position[i] += velocity[i] * h;
  }
}

void ObjectWorld::Impl::integrateRigid(const Object& object, RigidBody& body, double h) {
  // Newton–Euler: F = Σ f_i + M g, τ = Σ (x_i − X) × f_i about the centre of mass X.
  const DVec3 centre = body.centreOfMass();
  DVec3 total = gravity * body.mass(), torque{0, 0, 0};
  for (std::size_t i = object.first; i < object.first + object.count; ++i) {
    total += force[i];
    torque += cross(position[i] - centre, force[i]);
  }
  body.integrate(total, torque, h);
  const Mat3 r = body.rotation();
  const DVec3 x = body.centreOfMass(), v = body.velocity(), omega = body.angularVelocity();
  const std::vector<DVec3>& local = body.localPositions();
  for (std::size_t k = 0; k < object.count; ++k) {
    const DVec3 arm = r * local[k];
    position[object.first + k] = x + arm;
    velocity[object.first + k] = v + cross(omega, arm);
  }
}

ContactParticles ObjectWorld::Impl::contactParticles() const {
  return {position,
          velocity,
          published.radius,
          published.object,
          role,
          toD(settings.regionMin),
          toD(settings.regionMax),
          settings.periodic};
}

StaticParticles ObjectWorld::Impl::staticParticles() const {
  return {statics, settings.staticRadius, staticGrid};
}

// Contacts with a pushed particle are forces, summed at the substep's start; the XPBD
// deformables' other contacts are constraints, projected after the deformables' own at the
// predicted positions, with the kinematic objects already where the substep ends.
void ObjectWorld::Impl::substep(double h, const std::vector<Vec3>& externalForce) {
  const std::size_t n = position.size();
  std::fill(force.begin(), force.end(), DVec3{});
  if (contactsPossible && lightestPushedMass < std::numeric_limits<double>::infinity()) {
    const ContactParticles particles = contactParticles();
    addContactForces(settings.contact, particles, maxRadius, contactSearch, force);
    if (!statics.empty())
      addStaticContactForces(settings.contact, particles, statics, settings.staticRadius,
                             staticGrid, force);
    addContactImpulses(h);
  }
  if (!externalForce.empty())
    for (std::size_t i = 0; i < n; ++i) force[i] += toD(externalForce[i]);
  for (std::size_t b = 0; b < networks.size(); ++b)
    if (models[b] == DeformableModel::Springs)
      addSpringForces(networks[b], position, velocity, force);

  for (std::size_t b = 0; b < networks.size(); ++b) {
    SpringNetwork& net = networks[b];
    if (models[b] == DeformableModel::Xpbd) {
      xpbdPredict(net, xpbd[b], h, gravity, force, position, velocity);
      continue;
    }
    integrateDeformable(net, h);
    breakOverstretched(net, position, published.cut);
  }
  time += h;
  for (const Object& object : objects) {
    if (object.motion == ObjectMotion::Rigid) integrateRigid(object, rigid[object.body], h);
    if (object.motion == ObjectMotion::Kinematic) placeKinematic(object);
  }
  projectXpbd(h);
}

void ObjectWorld::Impl::keepVolumes() {
  for (std::size_t o : settings.liquidFilled) {
    const Object& object = objects.at(o);
    if (object.motion != ObjectMotion::Deformable || models[object.body] != DeformableModel::Xpbd ||
        !object.shape.enclosesVolume)
      continue;
    std::vector<std::uint32_t> surface;
    for (std::size_t i = object.first; i < object.first + object.count; ++i)
      if (published.surface[i]) surface.push_back(std::uint32_t(i));
    const SpringNetwork& net = networks[object.body];
    volumes.push_back(makeVolumeConstraint(
        o, object.body, std::move(surface), enclosedVolume(object.shape.desc, object.shape),
        position, published.normal, net.first, net.neighbourStart, net.neighbours));
  }
}

void ObjectWorld::Impl::projectXpbd(double h) {
  if (lightestProjectedMass == std::numeric_limits<double>::infinity()) return;
  for (std::size_t b = 0; b < networks.size(); ++b)
    if (models[b] == DeformableModel::Xpbd) xpbdProject(networks[b], xpbd[b], h, position);
  for (const VolumeConstraint& v : volumes)
    if (networks[v.network].brokenCount == 0) projectVolume(v, inverseMass, position);
  const StaticParticles walls = staticParticles();
  if (contactsPossible) {
    selectTouching(position, published.radius, walls, contactConstraints);
    projectContactConstraints(settings.contact, h, inverseMass, published.radius, published.object,
                              walls, contactConstraints, position, contactImpulse);
  }
  for (std::size_t b = 0; b < networks.size(); ++b)
    if (models[b] == DeformableModel::Xpbd)
      xpbdFinish(networks[b], xpbd[b], h, position, velocity, published.cut);
  if (contactsPossible)
    dampContactConstraints(settings.contact, h, inverseMass, published.object, walls,
                           contactConstraints, position, velocity, contactImpulse);
}

// While `force` holds the contacts alone.
void ObjectWorld::Impl::addContactImpulses(double h) {
  for (std::size_t o = 0; o < objects.size(); ++o) {
    DVec3 sum{};
    for (std::size_t i = objects[o].first; i < objects[o].first + objects[o].count; ++i)
      sum += force[i];
    contactImpulse[o] += sum * h;
  }
}

void ObjectWorld::Impl::publish() {
  const std::size_t n = position.size();
  for (std::size_t i = 0; i < n; ++i) {
    published.position[i] = toF(position[i]);
    published.velocity[i] = toF(velocity[i]);
  }
  for (const Object& object : objects) {
    Mat3 rotation = Mat3::identity();
    if (object.motion == ObjectMotion::Deformable) {
      updateNormals(networks[object.body], position, restNormal, published.pinned,
                    published.normal);
      continue;
    }
    if (object.motion == ObjectMotion::Rigid) rotation = rigid[object.body].rotation();
    if (object.motion == ObjectMotion::Kinematic) rotation = paths[object.body].at(time).rotation;
    for (std::size_t i = object.first; i < object.first + object.count; ++i)
      published.normal[i] = toF(normalized(rotation * restNormal[i]));
  }
}

// Moves the whole object, so that no spring, bending triple or volume spans a face; the
// contacts meet it across the face through its images. Kinematic objects follow their paths,
// and a deformable held by pinned particles stays where they hold it.
void ObjectWorld::Impl::wrapAcrossPeriodicFaces() {
  if (!settings.periodic.any()) return;
  for (const Object& object : objects) {
    if (object.motion == ObjectMotion::Kinematic) continue;
    const std::size_t end = object.first + object.count;
    if (std::any_of(published.pinned.begin() + std::ptrdiff_t(object.first),
                    published.pinned.begin() + std::ptrdiff_t(end),
                    [](std::uint8_t pinned) { return pinned != 0; }))
      continue;
    DVec3 centre{0, 0, 0};
    if (object.motion == ObjectMotion::Rigid) {
      centre = rigid[object.body].centreOfMass();
    } else {
      for (std::size_t i = object.first; i < end; ++i) centre += position[i];
      centre = centre / double(object.count);  // equal masses
    }
    const DVec3 shift = settings.periodic.shiftInto(centre);
    if (shift.x == 0.0 && shift.y == 0.0 && shift.z == 0.0) continue;
    for (std::size_t i = object.first; i < end; ++i) position[i] += shift;
    if (object.motion == ObjectMotion::Rigid) {
      RigidBody::Motion m = rigid[object.body].motion();
      m.position += shift;
      rigid[object.body].setMotion(m);
    }
  }
}

double ObjectWorld::Impl::stableSubstep() const {
  double h = std::numeric_limits<double>::infinity();
  if (shortestSpringStep < std::numeric_limits<double>::infinity()) {
    h = std::min(h, kStepPerOmega * shortestSpringStep);
    if (fastestSpringDamping > 0.0) h = std::min(h, kStepPerDampingRate / fastestSpringDamping);
  }
  if (contactsPossible) {
    // Constraint contacts bound nothing; forces do, on the lightest thing they push (an XPBD
    // particle too, when pushed particles may meet it).
    const double mass = lightestPushedMass < std::numeric_limits<double>::infinity()
                            ? std::min(lightestPushedMass, lightestProjectedMass)
                            : std::numeric_limits<double>::infinity();
    const ContactCoefficients& k = settings.contact;
    if (k.spring > 0.0f && mass < std::numeric_limits<double>::infinity())
      h = std::min(h, kStepPerOmega * springTimeStep(mass, double(k.spring), 1.0));
    const double dampingRate = (double(k.damping) + double(k.shear)) / mass;
    if (dampingRate > 0.0) h = std::min(h, kStepPerDampingRate / dampingRate);
    h = std::min(h, travelTimeStep(kMaxTravelPerRadius * double(minRadius), fastestInRegion()));
  }
  return h;
}

double ObjectWorld::Impl::fastestInRegion() const {
  double fastest = 0.0;
  const DVec3 lo = toD(settings.regionMin), hi = toD(settings.regionMax);
  for (std::size_t i = 0; i < velocity.size(); ++i) {
    const DVec3& x = position[i];
    const bool inRegion =
        x.x >= lo.x && x.y >= lo.y && x.z >= lo.z && x.x <= hi.x && x.y <= hi.y && x.z <= hi.z;
    if (inRegion) fastest = std::max(fastest, norm(velocity[i]));
  }
  return fastest;
}

// Two particles at the fastest speed close by 2 v dt in the step; the margin doubles that for
// what they gain in it, and adds a substep's travel for a pair that starts at rest.
void ObjectWorld::Impl::findContactCandidates(double dt) {
  if (!contactsPossible || lightestProjectedMass == std::numeric_limits<double>::infinity()) return;
  const double margin = 4.0 * fastestInRegion() * dt + kMaxTravelPerRadius * double(minRadius);
  sph::objects::findContactCandidates(contactParticles(), maxRadius, margin, staticParticles(),
                                      contactConstraints);
}

ObjectWorld::ObjectWorld(const std::vector<ObjectDesc>& objects, const WorldSettings& settings)
    : impl_(std::make_unique<Impl>()) {
  Impl& w = *impl_;
  w.settings = settings;
  w.gravity = toD(settings.gravity);
  for (std::size_t i = 0; i < objects.size(); ++i) w.addObject(objects[i], i);
  const std::size_t n = w.position.size();
  w.force.assign(n, DVec3{});
  w.contactImpulse.assign(objects.size(), DVec3{});
  w.contactForce.assign(objects.size(), DVec3{});
  w.published.position.resize(n);
  w.published.velocity.resize(n);
  w.published.normal.resize(n);
  const ContactCoefficients& k = settings.contact;
  const bool anyMovable = std::find(w.movable.begin(), w.movable.end(), 1) != w.movable.end();
  for (const Vec3& x : settings.staticParticles) w.statics.push_back(toD(x));
  if (!w.statics.empty()) w.staticGrid.build(w.statics, 2.0 * double(settings.staticRadius));
  w.contactConstraints.space = settings.periodic;
  w.contactsPossible = (objects.size() >= 2 || !w.statics.empty()) && anyMovable &&
                       (k.spring > 0.0f || k.damping > 0.0f || k.shear > 0.0f);
  w.publish();
  w.keepVolumes();  // from the normals just published
}

ObjectWorld::~ObjectWorld() = default;
ObjectWorld::ObjectWorld(ObjectWorld&&) noexcept = default;
ObjectWorld& ObjectWorld::operator=(ObjectWorld&&) noexcept = default;

std::size_t ObjectWorld::objectCount() const {
  return impl_->objects.size();
}

const ParticleState& ObjectWorld::particles() const {
  return impl_->published;
}

double ObjectWorld::time() const {
  return impl_->time;
}

const PeriodicSpace& ObjectWorld::periodicSpace() const {
  return impl_->settings.periodic;
}

Vec3 ObjectWorld::contactForce(std::size_t object) const {
  return toF(impl_->contactForce.at(object));
}

const DrawnSurface& ObjectWorld::drawnSurface(std::size_t object) const {
  return impl_->objects.at(object).drawn;
}

ObjectInfo ObjectWorld::info(std::size_t object) const {
  const Impl& w = *impl_;
  const Impl::Object& o = w.objects.at(object);
  ObjectInfo info;
  info.name = o.name;
  info.motion = o.motion;
  info.firstParticle = o.first;
  info.particleCount = o.count;
  DVec3 moment{0, 0, 0}, momentum{0, 0, 0};
  for (std::size_t i = o.first; i < o.first + o.count; ++i) {
    const double m = w.published.mass[i];
    info.mass += m;
    moment += w.position[i] * m;
    momentum += w.velocity[i] * m;
  }
  info.centreOfMass = toF(moment / info.mass);
  info.contactForce = toF(w.contactForce[object]);
  info.startCentre = toF(o.initialCentre);
  info.velocity = toF(momentum / info.mass);
  if (o.motion == ObjectMotion::Rigid) {
    info.centreOfMass = toF(w.rigid[o.body].centreOfMass());
    info.velocity = toF(w.rigid[o.body].velocity());
  }
  if (o.motion == ObjectMotion::Deformable) {
    info.springs = w.networks[o.body].springs.size();
    info.brokenSprings = w.networks[o.body].brokenCount;
  }
  for (const VolumeConstraint& v : w.volumes)
    if (v.object == object)
      info.volumeRatio = enclosedVolume(v, w.position, w.published.normal) / v.restVolume;
  return info;
}

void ObjectWorld::step(double dt, const std::vector<Vec3>& externalForce) {
  Impl& w = *impl_;
  if (!externalForce.empty() && externalForce.size() != w.position.size())
    throw std::invalid_argument("ObjectWorld::step: externalForce has " +
                                std::to_string(externalForce.size()) + " entries for " +
                                std::to_string(w.position.size()) + " particles");
  if (!(dt > 0.0)) return;
  const double stable = w.stableSubstep();
  double count = 1.0;
  if (stable > 0.0 && std::isfinite(stable)) count = std::min(std::ceil(dt / stable), kMaxSubsteps);
  // XPBD deformables take at least their own substeps; more, when contacts need them, only
  // shorten theirs.
  count = std::max(count, double(w.xpbdSubsteps));
  const std::size_t substeps = std::size_t(std::max(count, 1.0));
  const double start = w.time, h = dt / double(substeps);
  std::fill(w.contactImpulse.begin(), w.contactImpulse.end(), DVec3{});
  w.findContactCandidates(dt);
  for (VolumeConstraint& v : w.volumes)
    beginVolumeStep(v, w.position, w.published.normal, w.inverseMass);
  for (std::size_t s = 0; s < substeps; ++s) w.substep(h, externalForce);
  w.time = start + dt;  // no drift from summing h
  for (std::size_t o = 0; o < w.objects.size(); ++o) w.contactForce[o] = w.contactImpulse[o] / dt;
  for (const Impl::Object& object : w.objects)
    if (object.motion == ObjectMotion::Kinematic) w.placeKinematic(object);
  w.wrapAcrossPeriodicFaces();
  w.publish();
}

double ObjectWorld::stableSubstep() const {
  return impl_->stableSubstep();
}

bool ObjectWorld::interiorContains(std::size_t object, Vec3 p, float margin) const {
  return impl_->objects.at(object).shape.interiorContains(toD(p), margin);
}

void ObjectWorld::steer(std::size_t object, Vec3 offset, double arriveIn) {
  Impl& w = *impl_;
  const Impl::Object& o = w.objects.at(object);
  if (o.motion != ObjectMotion::Kinematic)
    throw std::invalid_argument("steer: object '" + o.name + "' is not kinematic");
  if (!(arriveIn > 0.0)) throw std::invalid_argument("steer: expected a time > 0");
  w.paths[o.body].steer(w.time, toD(offset), arriveIn);
}

bool ObjectWorld::enclosesVolume(std::size_t object) const {
  return impl_->objects.at(object).shape.enclosesVolume;
}

namespace {

void appendVectors(std::vector<double>& out, const std::vector<DVec3>& v) {
  for (const DVec3& x : v) out.insert(out.end(), {x.x, x.y, x.z});
}

std::vector<DVec3> readVectors(const std::vector<double>& in, std::size_t count, const char* what) {
  if (in.size() != 3 * count)
    throw std::invalid_argument(std::string("ObjectWorld::restore: ") + what + " of " +
                                std::to_string(in.size() / 3) + " entries for " +
                                std::to_string(count));
  std::vector<DVec3> out(count);
  for (std::size_t k = 0; k < count; ++k) out[k] = DVec3{in[3 * k], in[3 * k + 1], in[3 * k + 2]};
  return out;
}

}  // namespace

WorldState ObjectWorld::state() const {
  const Impl& w = *impl_;
  WorldState s;
  s.time = w.time;
  appendVectors(s.position, w.position);
  appendVectors(s.velocity, w.velocity);
  appendVectors(s.contactForce, w.contactForce);
  s.cut = w.published.cut;
  for (const RigidBody& body : w.rigid) {
    const RigidBody::Motion m = body.motion();
    appendVectors(s.bodies, {m.position, m.velocity});
    s.bodies.insert(s.bodies.end(),
                    {m.orientation.w, m.orientation.x, m.orientation.y, m.orientation.z});
    appendVectors(s.bodies, {m.angularVelocityBody});
  }
  for (const SpringNetwork& net : w.networks)
    s.springBroken.insert(s.springBroken.end(), net.broken.begin(), net.broken.end());
  for (const XpbdConstraints& x : w.xpbd)
    s.bendingBroken.insert(s.bendingBroken.end(), x.bendingBroken.begin(), x.bendingBroken.end());
  for (const KinematicPath& path : w.paths) {
    s.pathKeyCounts.push_back(path.keyframes().size());
    s.pathKeys.insert(s.pathKeys.end(), path.keyframes().begin(), path.keyframes().end());
  }
  return s;
}

void ObjectWorld::restore(const WorldState& s) {
  Impl& w = *impl_;
  const auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("ObjectWorld::restore: ") + what);
  };
  std::vector<DVec3> position = readVectors(s.position, w.position.size(), "positions");
  std::vector<DVec3> velocity = readVectors(s.velocity, w.velocity.size(), "velocities");
  std::vector<DVec3> contactForce = readVectors(s.contactForce, w.objects.size(), "forces");
  require(s.cut.size() == w.published.cut.size(), "cut flags");
  require(s.bodies.size() == 13 * w.rigid.size(), "rigid bodies");
  std::size_t springs = 0, triples = 0, keys = 0;
  for (const SpringNetwork& net : w.networks) springs += net.broken.size();
  for (const XpbdConstraints& x : w.xpbd) triples += x.bendingBroken.size();
  require(s.springBroken.size() == springs, "springs");
  require(s.bendingBroken.size() == triples, "bending triples");
  require(s.pathKeyCounts.size() == w.paths.size(), "kinematic paths");
  for (std::uint64_t n : s.pathKeyCounts) keys += std::size_t(n);
  require(s.pathKeys.size() == keys, "keyframes");

  w.time = s.time;
  w.position = std::move(position);
  w.velocity = std::move(velocity);
  w.contactForce = std::move(contactForce);
  w.published.cut = s.cut;
  for (std::size_t b = 0; b < w.rigid.size(); ++b) {
    const double* m = &s.bodies[13 * b];
    w.rigid[b].setMotion({DVec3{m[0], m[1], m[2]}, DVec3{m[3], m[4], m[5]},
                          Quat{m[6], m[7], m[8], m[9]}, DVec3{m[10], m[11], m[12]}});
  }
  std::size_t at = 0;
  for (SpringNetwork& net : w.networks) {
    net.brokenCount = 0;
    for (std::uint8_t& broken : net.broken) {
      broken = s.springBroken[at++];
      net.brokenCount += broken ? 1 : 0;
    }
  }
  at = 0;
  for (XpbdConstraints& x : w.xpbd)
    for (std::uint8_t& broken : x.bendingBroken) broken = s.bendingBroken[at++];
  at = 0;
  for (std::size_t p = 0; p < w.paths.size(); ++p) {
    const std::size_t n = std::size_t(s.pathKeyCounts[p]);
    w.paths[p].setKeyframes(std::vector<KeyframeDesc>(s.pathKeys.begin() + std::ptrdiff_t(at),
                                                      s.pathKeys.begin() + std::ptrdiff_t(at + n)));
    at += n;
  }
  w.publish();
}

}  // namespace sph::objects
