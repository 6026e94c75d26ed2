#include "sim/scene_size.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "sph/core/constants.hpp"
#include "sph/error.hpp"

namespace sph::sim {

namespace {

// What a particle costs a run on the CPU: the peak memory of scenes/dam_break.json at spacings
// 0.004 and 0.003 m (62,500 and 148,137 fluid, 126,332 and 221,778 wall particles: 51 and
// 105 MB) gives about 500 bytes a fluid particle (its state, sort keys, SIMD copies, a
// neighbour list of 64 indices) and 120 a wall particle.
constexpr double kBytesPerFluidParticle = 512.0;
constexpr double kBytesPerWallParticle = 128.0;
// An object particle in the engine (double-precision state, springs to its neighbours within
// 2.2 spacings, contact candidates) and as the fluid sees it: the artery's 2,640 take about 3 MB.
constexpr double kBytesPerObjectParticle = 1024.0;

double cells(double extent, double spacing) {
  return std::max(0.0, std::round(extent / spacing));
}

double boxCells(const AxisBox& box, double spacing) {
  double n = 1.0;
  for (int a = 0; a < 3; ++a) n *= cells(box.max[a] - box.min[a], spacing);
  return n;
}

double boxArea(const AxisBox& box) {
  const double x = box.max[0] - box.min[0], y = box.max[1] - box.min[1],
               z = box.max[2] - box.min[2];
  return 2.0 * (x * y + y * z + z * x);
}

// A wall's particles: its surface over d², times its layers, a little more for the lattice's
// rounding and the layers outside a surface (always an over-estimate).
double wallParticles(const WallDesc& w, double d) {
  double area = 0.0;
  switch (w.kind) {
    case WallKind::Tank:
    case WallKind::Box: {
      AxisBox outer = w.box;
      for (int a = 0; a < 3; ++a) {
        outer.min[a] -= w.layers * d;
        outer.max[a] += w.layers * d;
      }
      area = boxArea(outer);
      break;
    }
    case WallKind::Sphere: {
      const double r = w.radius + w.layers * d;
      area = 4.0 * kPi * r * r;
      break;
    }
    case WallKind::Cylinder: {
      const double r = w.radius + w.layers * d;
      area = 2.0 * kPi * r * (w.length + 2.0 * w.layers * d) + 2.0 * kPi * r * r;
      break;
    }
    case WallKind::Plane: {
      const double e1 =
          std::sqrt(w.edge1[0] * w.edge1[0] + w.edge1[1] * w.edge1[1] + w.edge1[2] * w.edge1[2]);
      const double e2 =
          std::sqrt(w.edge2[0] * w.edge2[0] + w.edge2[1] * w.edge2[1] + w.edge2[2] * w.edge2[2]);
      area = (e1 + d) * (e2 + d);
      break;
    }
    case WallKind::Mesh:
      return 0.0;
  }
  return 1.5 * w.layers * area / (d * d);
}

// An object's particles: its volume over d³ when solid, else its surface over d² times its
// layers, with the same allowance as a wall's (an over-estimate; meshes are left out).
double objectParticles(const ObjectDesc& o, double fluidSpacing) {
  const ShapeDesc& s = o.shape;
  const double d = o.spacing > 0.0 ? o.spacing : fluidSpacing;
  const double r = s.radius, l = s.length;
  const Vec3d& e = s.halfExtents;
  double area = 0.0, volume = 0.0;
  switch (s.kind) {
    case ShapeKind::Box:
      area = 8.0 * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0]);
      volume = 8.0 * e[0] * e[1] * e[2];
      break;
    case ShapeKind::Sphere:
      area = 4.0 * kPi * r * r;
      volume = 4.0 / 3.0 * kPi * r * r * r;
      break;
    case ShapeKind::Capsule:
    case ShapeKind::Tube:
      area = 2.0 * kPi * r * l + 4.0 * kPi * r * r;
      volume = kPi * r * r * l + 4.0 / 3.0 * kPi * r * r * r;
      break;
    case ShapeKind::Mesh:
      return 0.0;
  }
  if (s.solid) return 1.5 * volume / (d * d * d) + area / (d * d);
  return 1.5 * std::max(1, s.layers) * area / (d * d);
}

double emitterParallelogramArea(const EmitterDesc& e) {
  const Vec3d& a = e.edge1;
  const Vec3d& b = e.edge2;
  const double x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2],
               z = a[0] * b[1] - a[1] * b[0];
  return std::sqrt(x * x + y * y + z * z);
}

std::string describeCount(double n) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3g", n);
  return text;
}

std::string describeBytes(double bytes) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3g GB", bytes / 1e9);
  return text;
}

}  // namespace

SceneSize estimateSize(const Scene& scene) {
  SceneSize size;
  const double d = scene.fluid.spacing;
  for (const FluidBlock& block : scene.fluid.blocks) size.fluidParticles += boxCells(block.box, d);
  for (const WallDesc& wall : scene.walls) size.wallParticles += wallParticles(wall, d);
  for (const ObjectDesc& object : scene.objects) size.objectParticles += objectParticles(object, d);
  // What the emitters put in over the run, no more than the domain holds at rest density.
  double emitted = 0.0;
  for (const EmitterDesc& e : scene.emitters) {
    const double area =
        e.shape == EmitterShape::Disc ? kPi * e.radius * e.radius : emitterParallelogramArea(e);
    const double running = std::max(0.0, std::min(e.end, scene.time.duration) - e.start);
    emitted += area / (d * d) * std::ceil(running * e.speed / d);
  }
  size.fluidParticles += std::min(emitted, boxCells(scene.domain.box, d));
  size.bytes = size.fluidParticles * kBytesPerFluidParticle +
               size.wallParticles * kBytesPerWallParticle +
               size.objectParticles * kBytesPerObjectParticle;
  return size;
}

double availableBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? double(pages) * double(pageSize) : HUGE_VAL;
}

void refuseIfTooLarge(const Scene& scene, double machineBytes) {
  const SceneSize size = estimateSize(scene);
  std::string makes = "the scene would make " + describeCount(size.fluidParticles) + " fluid" +
                      (size.objectParticles > 0.0 ? ", " : " and ") +
                      describeCount(size.wallParticles) + " wall";
  if (size.objectParticles > 0.0)
    makes += " and " + describeCount(size.objectParticles) + " object";
  makes += " particles, about " + describeBytes(size.bytes) + " of memory";
  const LimitsDesc& limits = scene.limits;
  if (limits.maxParticles > 0.0 &&
      size.fluidParticles + size.wallParticles + size.objectParticles > limits.maxParticles)
    throw InputError(scene.sourcePath + ": limits.max_particles: " + makes + ", more than the " +
                     describeCount(limits.maxParticles) +
                     " particles it allows; expected a larger spacing, smaller blocks or a "
                     "higher limit");
  if (limits.maxMemoryGb > 0.0 && size.bytes > 1e9 * limits.maxMemoryGb)
    throw InputError(scene.sourcePath + ": limits.max_memory_gb: " + makes + ", more than the " +
                     describeBytes(1e9 * limits.maxMemoryGb) +
                     " it allows; expected a larger spacing, smaller blocks or a higher limit");
  if (size.bytes <= machineBytes) return;
  // Blamed on what makes most of the memory.
  const bool objects = size.objectParticles * kBytesPerObjectParticle > 0.5 * size.bytes;
  throw InputError(scene.sourcePath + (objects ? ": objects: " : ": fluid.spacing: ") + makes +
                   ", more than this machine's " + describeBytes(machineBytes) +
                   (objects ? "; expected a larger object spacing or smaller objects"
                            : "; expected a larger spacing or smaller blocks"));
}

}  // namespace sph::sim
