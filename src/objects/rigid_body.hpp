// A rigid body made of particles (Meteer 2011, §4.3): Newton–Euler motion of the centre of mass and
// the orientation under the summed particle forces and torques.
#pragma once

#include <vector>

#include "objects/math3d.hpp"

namespace sph::objects {

class RigidBody {
 public:
  // From the particles at the initial pose; velocities in the world frame. The body frame is the
  // world frame at the start, centred on the centre of mass.
  RigidBody(const std::vector<DVec3>& position, const std::vector<double>& mass, double spacing,
            DVec3 velocity, DVec3 angularVelocity);

  // One substep of length h under a total force and a torque about the centre of mass, both
  // held constant over it.
  void integrate(DVec3 force, DVec3 torque, double h);

  double mass() const { return mass_; }
  DVec3 centreOfMass() const { return position_; }
  DVec3 velocity() const { return velocity_; }
  Mat3 rotation() const { return rotationMatrix(orientation_); }
  DVec3 angularVelocity() const { return rotation() * angularVelocityBody_; }
  // World-frame angular momentum about the centre of mass, L = R I_body ω_body.
  DVec3 angularMomentum() const { return rotation() * (inertiaBody_ * angularVelocityBody_); }
  // A lower bound on the mass a contact at any particle feels, 1 / (1/M + r_max² |I⁻¹|)
  // (|I⁻¹| as the Frobenius norm bounds its largest eigenvalue), for the substep bound.
  double contactMass() const;
  // What moves: for a saved simulation state, and back.
  struct Motion {
    DVec3 position, velocity;
    Quat orientation;
    DVec3 angularVelocityBody;
  };
  Motion motion() const { return {position_, velocity_, orientation_, angularVelocityBody_}; }
  void setMotion(const Motion& m) {
    position_ = m.position;
    velocity_ = m.velocity;
    orientation_ = m.orientation;
    angularVelocityBody_ = m.angularVelocityBody;
  }
  // Offsets of the particles from the centre of mass in the body frame.
  const std::vector<DVec3>& localPositions() const { return local_; }

 private:
  double mass_ = 0.0;
  Mat3 inertiaBody_, inverseInertiaBody_;
  std::vector<DVec3> local_;
  DVec3 position_, velocity_;
  Quat orientation_;
  DVec3 angularVelocityBody_;
};

}  // namespace sph::objects
