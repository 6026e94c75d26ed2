// Rigid bodies (src/objects/rigid_body.*): free fall, a = F/m, dL/dt = τ, and torque-free
// spin that conserves angular momentum and energy while the body tumbles.
#include <gtest/gtest.h>

#include <cmath>

#include "object_scenes.hpp"

namespace sph::objects {
namespace {

using test::box;
using test::settings;

struct Moments {
  Vec3 centre, velocity;
  double mass = 0;
  double L[3] = {0, 0, 0};  // Σ m (x − X) × (v − V)
  double kinetic = 0;       // ½ Σ m |v − V|²
};

// Measured from the published particles alone.
Moments measure(const ParticleState& p) {
  Moments m;
  double c[3] = {0, 0, 0}, v[3] = {0, 0, 0};
  for (std::size_t i = 0; i < p.size(); ++i) {
    m.mass += p.mass[i];
    c[0] += p.mass[i] * double(p.position[i].x);
    c[1] += p.mass[i] * double(p.position[i].y);
    c[2] += p.mass[i] * double(p.position[i].z);
    v[0] += p.mass[i] * double(p.velocity[i].x);
    v[1] += p.mass[i] * double(p.velocity[i].y);
    v[2] += p.mass[i] * double(p.velocity[i].z);
  }
  for (double& x : c) x /= m.mass;
  for (double& x : v) x /= m.mass;
  m.centre = {float(c[0]), float(c[1]), float(c[2])};
  m.velocity = {float(v[0]), float(v[1]), float(v[2])};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r[3] = {p.position[i].x - c[0], p.position[i].y - c[1], p.position[i].z - c[2]};
    const double u[3] = {p.velocity[i].x - v[0], p.velocity[i].y - v[1], p.velocity[i].z - v[2]};
    m.L[0] += p.mass[i] * (r[1] * u[2] - r[2] * u[1]);
    m.L[1] += p.mass[i] * (r[2] * u[0] - r[0] * u[2]);
    m.L[2] += p.mass[i] * (r[0] * u[1] - r[1] * u[0]);
    m.kinetic += 0.5 * p.mass[i] * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  }
  return m;
}

double norm3(const double* a) {
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

TEST(RigidBody, FreeFallFollowsTheParabola) {
  ObjectDesc d = box({0, 1, 0}, {0.05, 0.03, 0.02}, 0.01);
  d.velocity = {1.0, 2.0, -0.5};
  const float g = -9.81f;
  ObjectWorld world({d}, settings({0, g, 0}));
  EXPECT_TRUE(std::isinf(world.stableSubstep()));  // nothing to resolve: one substep a step
  const std::vector<Vec3> start = world.particles().position;
  const double dt = 1e-3;
  const int steps = 1000;
  for (int s = 0; s < steps; ++s) world.step(dt, {});
  const double t = steps * dt;
  EXPECT_NEAR(world.time(), t, 1e-12);
  const ObjectInfo info = world.info(0);
  // Symplectic Euler: x_n = x0 + v0 t + ½ g t² + ½ g t dt, first order in dt.
  const double exactY = 1.0 + 2.0 * t + 0.5 * g * t * t;
  EXPECT_NEAR(info.centreOfMass.x, 1.0 * t, 1e-5);
  EXPECT_NEAR(info.centreOfMass.z, -0.5 * t, 1e-5);
  EXPECT_NEAR(info.centreOfMass.y, exactY, 0.5 * std::abs(g) * t * dt * 1.01);
  EXPECT_NEAR(info.centreOfMass.y, exactY + 0.5 * g * t * dt, 1e-5);
  EXPECT_NEAR(info.velocity.y, 2.0 + g * t, 1e-5);
  // Every particle moved with the body, without turning.
  const ParticleState& p = world.particles();
  const Vec3 shift = p.position[0] - start[0];
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_NEAR(test::distance(p.position[i] - start[i], shift), 0.0, 2e-6);
    EXPECT_NEAR(test::distance(p.velocity[i], info.velocity), 0.0, 1e-5);
  }
}

TEST(RigidBody, ConstantForceGivesAccelerationFOverM) {
  ObjectDesc d = box({0, 0, 0}, {0.05, 0.03, 0.02}, 0.01);
  ObjectWorld world({d}, settings());
  const std::size_t n = world.particles().size();
  const double mass = world.info(0).mass;
  const Vec3 perParticle{2e-3f, -1e-3f, 0.5e-3f};
  const std::vector<Vec3> force(n, perParticle);
  for (int s = 0; s < 200; ++s) world.step(1e-3, force);
  const double t = 0.2;
  const Vec3 v = world.info(0).velocity;
  const double ax = n * perParticle.x / mass, ay = n * perParticle.y / mass;
  EXPECT_NEAR(v.x, ax * t, 1e-4 * ax * t);
  EXPECT_NEAR(v.y, ay * t, 1e-4 * std::abs(ay * t));
  // A uniform force has no torque: the body does not start turning.
  const Moments m = measure(world.particles());
  EXPECT_LT(norm3(m.L), 1e-12);
}

TEST(RigidBody, TorqueChangesAngularMomentumAtItsRate) {
  ObjectDesc d = box({0, 0, 0}, {0.05, 0.03, 0.02}, 0.01);
  ObjectWorld world({d}, settings());
  const ParticleState& p0 = world.particles();
  // Push the particle at the corner (+x, +y, +z) along −y.
  std::size_t corner = 0;
  for (std::size_t i = 0; i < p0.size(); ++i)
    if (p0.position[i].x > 0.049f && p0.position[i].y > 0.029f && p0.position[i].z > 0.019f)
      corner = i;
  const Vec3 r = p0.position[corner];
  std::vector<Vec3> force(p0.size(), Vec3{0, 0, 0});
  force[corner] = {0, -0.01f, 0};
  const double t = 0.01;
  for (int s = 0; s < 10; ++s) world.step(t / 10, force);
  const Moments m = measure(world.particles());
  // L = ∫ r × F dt ≈ r × F t while the body has hardly turned: r × (0, −F, 0) = (F z, 0, −F x).
  EXPECT_NEAR(m.L[0], 0.01 * r.z * t, 0.01 * 0.01 * r.z * t);
  EXPECT_NEAR(m.L[1], 0.0, 1e-3 * 0.01 * r.x * t);
  EXPECT_NEAR(m.L[2], -0.01 * r.x * t, 0.01 * 0.01 * r.x * t);
  EXPECT_NEAR(m.velocity.y, -0.01 * t / m.mass, 1e-3 * 0.01 * t / m.mass);
}

// ω = I⁻¹ L with I = Σ m (|r|² 1 − r rᵀ) of the particles as they are now (Cramer's rule).
void angularVelocity(const ParticleState& p, const Moments& m, double omega[3]) {
  double I[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r[3] = {p.position[i].x - m.centre.x, p.position[i].y - m.centre.y,
                         p.position[i].z - m.centre.z};
    const double rr = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) I[a][b] += p.mass[i] * ((a == b ? rr : 0.0) - r[a] * r[b]);
  }
  auto det = [](const double M[3][3]) {
    return M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
           M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
           M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  };
  const double d = det(I);
  for (int c = 0; c < 3; ++c) {
    double M[3][3];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) M[a][b] = b == c ? m.L[a] : I[a][b];
    omega[c] = det(M) / d;
  }
}

TEST(RigidBody, TorqueFreeSpinConservesAngularMomentumWhileTumbling) {
  // Spin mostly about the intermediate principal axis (y), which is unstable: the angular
  // velocity wanders through the body (by 0.7 rad within the second) while L must stay put.
  ObjectDesc d = box({0, 0, 0}, {0.1, 0.05, 0.02}, 0.01);
  d.angularVelocity = {2.0, 6.0, 0.5};
  ObjectWorld world({d}, settings());
  const Moments start = measure(world.particles());
  double omega0[3];
  angularVelocity(world.particles(), start, omega0);
  EXPECT_NEAR(omega0[1], 6.0, 1e-4);  // the particles carry the initial spin
  const double l0 = norm3(start.L);
  double largestTurn = 0.0;  // of ω away from its start, rad
  for (int s = 1; s <= 1000; ++s) {
    world.step(1e-3, {});
    if (s % 50 != 0) continue;
    const Moments m = measure(world.particles());
    const double l = norm3(m.L);
    EXPECT_NEAR(l, l0, 1e-3 * l0) << "t = " << s * 1e-3;
    const double cosine =
        (m.L[0] * start.L[0] + m.L[1] * start.L[1] + m.L[2] * start.L[2]) / (l * l0);
    EXPECT_GT(cosine, std::cos(1e-3)) << "L turned by more than 1e-3 rad at t = " << s * 1e-3;
    EXPECT_NEAR(m.kinetic, start.kinetic, 1e-3 * start.kinetic);
    double omega[3];
    angularVelocity(world.particles(), m, omega);
    const double c = (omega[0] * omega0[0] + omega[1] * omega0[1] + omega[2] * omega0[2]) /
                     (norm3(omega) * norm3(omega0));
    largestTurn = std::max(largestTurn, std::acos(std::clamp(c, -1.0, 1.0)));
  }
  // Not a steady spin: ω wandered far from L's direction, so the gyroscopic term was at work.
  EXPECT_GT(largestTurn, 0.5);
}

}  // namespace
}  // namespace sph::objects
