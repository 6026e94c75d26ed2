#include "sim/emitters.hpp"

#include <algorithm>
#include <cmath>

namespace sph::sim {
namespace {

Vec3d operator+(const Vec3d& a, const Vec3d& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
Vec3d operator*(const Vec3d& a, double s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}
double dotD(const Vec3d& a, const Vec3d& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3d crossD(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3d unit(const Vec3d& a) {
  return a * (1.0 / std::sqrt(dotD(a, a)));
}
Vec3 toFloat(const Vec3d& a) {
  return Vec3{float(a[0]), float(a[1]), float(a[2])};
}

// Two unit vectors completing n to an orthonormal frame.
void frameAround(const Vec3d& n, Vec3d& u, Vec3d& v) {
  const Vec3d helper = std::fabs(n[0]) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  u = unit(crossD(helper, n));
  v = crossD(n, u);
}

// Cell centres of a square lattice of spacing d, symmetric about the centre, inside radius r.
std::vector<Vec3d> discLattice(const Vec3d& n, double r, double d) {
  Vec3d u, v;
  frameAround(n, u, v);
  const int reach = int(std::ceil(r / d));
  std::vector<Vec3d> points;
  for (int j = -reach; j < reach; ++j) {
    for (int i = -reach; i < reach; ++i) {
      const double a = (i + 0.5) * d;
      const double b = (j + 0.5) * d;
      if (a * a + b * b < r * r) points.push_back(u * a + v * b);
    }
  }
  return points;
}

// The parallelogram's cells, as near d across as whole numbers of them fit.
std::vector<Vec3d> rectangleLattice(const Vec3d& e1, const Vec3d& e2, double d) {
  const int n1 = std::max(1, int(std::lround(std::sqrt(dotD(e1, e1)) / d)));
  const int n2 = std::max(1, int(std::lround(std::sqrt(dotD(e2, e2)) / d)));
  std::vector<Vec3d> points;
  for (int j = 0; j < n2; ++j)
    for (int i = 0; i < n1; ++i) points.push_back(e1 * ((i + 0.5) / n1) + e2 * ((j + 0.5) / n2));
  return points;
}

}  // namespace

static_assert(kMaxEmitters <= fluid::kInflowSlots, "an emitter the stage has no slot for");

Emitters::Emitters(const Scene& scene) : spacing_(scene.fluid.spacing) {
  const double d = spacing_;
  for (const EmitterDesc& desc : scene.emitters) {
    Emitter e;
    e.name = desc.name;
    e.speed = desc.speed;
    e.start = desc.start;
    e.end = desc.end;
    fluid::InflowZone& z = e.zone;
    if (desc.shape == EmitterShape::Disc) {
      e.origin = desc.center;
      e.normal = unit(desc.direction);
      e.layer = discLattice(e.normal, desc.radius, d);
      z.radius = float(desc.radius);
      z.dual1 = z.dual2 = Vec3{0, 0, 0};
    } else {
      e.origin = desc.corner;
      e.normal = unit(crossD(desc.edge1, desc.edge2));
      e.layer = rectangleLattice(desc.edge1, desc.edge2, d);
      // a = dual1·r, b = dual2·r for r = a e1 + b e2 + c n.
      const Vec3d c1 = crossD(desc.edge2, e.normal);
      const Vec3d c2 = crossD(e.normal, desc.edge1);
      z.dual1 = toFloat(c1 * (1.0 / dotD(desc.edge1, c1)));
      z.dual2 = toFloat(c2 * (1.0 / dotD(desc.edge2, c2)));
      z.radius = 0.0f;
    }
    z.origin = toFloat(e.origin);
    z.normal = toFloat(e.normal);
    // From just behind the plane (a layer enters at it) to two spacings on: the layer put
    // last and the one before it, which together hold the next layer's neighbourhood.
    z.behind = float(-0.5 * d);
    z.depth = float(2.0 * d);
    z.speed = float(desc.speed);
    emitters_.push_back(std::move(e));
  }
}

double Emitters::particleRate(std::size_t k) const {
  const Emitter& e = emitters_[k];
  return double(e.layer.size()) * e.speed / spacing_;
}

std::uint64_t Emitters::layersBy(const Emitter& e, double t) const {
  if (t <= e.start) return 0;
  const double until = std::min(t, e.end);
  // Layers j with start + j d / U < until (and, when `until` is `end`, before it).
  const double periods = (until - e.start) * e.speed / spacing_;
  return std::uint64_t(std::ceil(periods));
}

std::uint64_t Emitters::emittedBy(double t) const {
  std::uint64_t n = 0;
  for (const Emitter& e : emitters_) n += layersBy(e, t) * e.layer.size();
  return n;
}

fluid::InflowZones Emitters::zones() const {
  fluid::InflowZones out;
  for (const Emitter& e : emitters_) out.zone[out.count++] = e.zone;
  return out;
}

NewParticles Emitters::emit(double t) {
  NewParticles out;
  for (Emitter& e : emitters_) {
    const std::uint64_t due = layersBy(e, t);
    const Vec3d velocity = e.normal * e.speed;
    for (; e.layers < due; ++e.layers) {
      const double moment = e.start + double(e.layers) * spacing_ / e.speed;
      const Vec3d offset = e.origin + e.normal * (e.speed * (t - moment));
      for (const Vec3d& p : e.layer) {
        out.position.push_back(toFloat(offset + p));
        out.velocity.push_back(toFloat(velocity));
      }
      e.emitted += e.layer.size();
    }
  }
  return out;
}

void Emitters::save(StateWriter& out) const {
  out.value(std::uint64_t(emitters_.size()));
  for (const Emitter& e : emitters_) {
    out.value(e.layers);
    out.value(e.emitted);
  }
}

void Emitters::load(StateReader& in) {
  if (in.value<std::uint64_t>() != emitters_.size()) in.mismatch("its emitters");
  for (Emitter& e : emitters_) {
    e.layers = in.value<std::uint64_t>();
    e.emitted = in.value<std::uint64_t>();
  }
}

}  // namespace sph::sim
