#include "objects/rigid_body.hpp"

#include <algorithm>
#include <cmath>

namespace sph::objects {

RigidBody::RigidBody(const std::vector<DVec3>& position, const std::vector<double>& mass,
                     double spacing, DVec3 velocity, DVec3 angularVelocity) {
  DVec3 moment{0, 0, 0};
  for (std::size_t i = 0; i < position.size(); ++i) {
    mass_ += mass[i];
    moment += position[i] * mass[i];
  }
  position_ = moment / mass_;
  velocity_ = velocity;
  angularVelocityBody_ = angularVelocity;  // body frame = world frame at t = 0
  local_.resize(position.size());
  // I = Σ m (|r|² 1 − r rᵀ) over point masses, so that the particles' own angular momentum
  // Σ m r × v is what is conserved.
  for (std::size_t i = 0; i < position.size(); ++i) {
    const DVec3 r = position[i] - position_;
    local_[i] = r;
    const double rr[3] = {r.x, r.y, r.z};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        inertiaBody_.m[a][b] += mass[i] * ((a == b ? dot(r, r) : 0.0) - rr[a] * rr[b]);
  }
  // Particles on a line (or a single one) leave I singular: count each as a cube of edge
  // `spacing` (its own m s²/6 about every axis) to keep the rotation defined.
  const Mat3& m = inertiaBody_;
  const double trace = m.m[0][0] + m.m[1][1] + m.m[2][2];
  const double det = m.m[0][0] * (m.m[1][1] * m.m[2][2] - m.m[1][2] * m.m[2][1]) -
                     m.m[0][1] * (m.m[1][0] * m.m[2][2] - m.m[1][2] * m.m[2][0]) +
                     m.m[0][2] * (m.m[1][0] * m.m[2][1] - m.m[1][1] * m.m[2][0]);
  if (!(det > 1e-9 * trace * trace * trace))
    for (int a = 0; a < 3; ++a) inertiaBody_.m[a][a] += mass_ * spacing * spacing / 6.0;
  inverseInertiaBody_ = inverse(inertiaBody_);
}

double RigidBody::contactMass() const {
  double armSquared = 0.0, inverseNorm = 0.0;
  for (const DVec3& r : local_) armSquared = std::max(armSquared, dot(r, r));
  for (const auto& row : inverseInertiaBody_.m)
    for (double v : row) inverseNorm += v * v;
  return 1.0 / (1.0 / mass_ + armSquared * std::sqrt(inverseNorm));
}

namespace {

struct AngularState {
  Quat q;
  DVec3 omega;  // body frame
};

// The rotational equations of motion in the body frame: q̇ = ½ q ⊗ (0, ω) and Euler's
// equations I ω̇ = τ_body − ω × (I ω) (the gyroscopic term).
AngularState derivative(const AngularState& s, const Mat3& inertia, const Mat3& inverseInertia,
                        DVec3 torqueWorld) {
  const Quat dq = s.q * Quat{0.0, s.omega.x, s.omega.y, s.omega.z};
  const DVec3 torqueBody = transpose(rotationMatrix(s.q)) * torqueWorld;
  const DVec3 domega = inverseInertia * (torqueBody - cross(s.omega, inertia * s.omega));
  return {{0.5 * dq.w, 0.5 * dq.x, 0.5 * dq.y, 0.5 * dq.z}, domega};
}

AngularState advance(const AngularState& s, const AngularState& d, double h) {
  return {{s.q.w + h * d.q.w, s.q.x + h * d.q.x, s.q.y + h * d.q.y, s.q.z + h * d.q.z},
          s.omega + d.omega * h};
}

}  // namespace

void RigidBody::integrate(DVec3 force, DVec3 torque, double h) {
  // Translation: symplectic Euler, like the deformables.
  velocity_ += force * (h / mass_);
  position_ += velocity_ * h;
  // Rotation: classical Runge–Kutta on (q, ω_body); the gyroscopic term makes explicit Euler
  // gain energy in free spin, RK4 keeps |L| to ~(ωh)⁴ per substep.
  const AngularState s0{orientation_, angularVelocityBody_};
  const AngularState k1 = derivative(s0, inertiaBody_, inverseInertiaBody_, torque);
  const AngularState k2 =
      derivative(advance(s0, k1, 0.5 * h), inertiaBody_, inverseInertiaBody_, torque);
  const AngularState k3 =
      derivative(advance(s0, k2, 0.5 * h), inertiaBody_, inverseInertiaBody_, torque);
  const AngularState k4 = derivative(advance(s0, k3, h), inertiaBody_, inverseInertiaBody_, torque);
  const double w = h / 6.0;
  const Quat q{s0.q.w + w * (k1.q.w + 2 * k2.q.w + 2 * k3.q.w + k4.q.w),
               s0.q.x + w * (k1.q.x + 2 * k2.q.x + 2 * k3.q.x + k4.q.x),
               s0.q.y + w * (k1.q.y + 2 * k2.q.y + 2 * k3.q.y + k4.q.y),
               s0.q.z + w * (k1.q.z + 2 * k2.q.z + 2 * k3.q.z + k4.q.z)};
  orientation_ = normalized(q);
  angularVelocityBody_ = s0.omega + (k1.omega + 2.0 * k2.omega + 2.0 * k3.omega + k4.omega) * w;
}

}  // namespace sph::objects
