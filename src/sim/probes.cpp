#include "sim/probes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sph::sim {

namespace {

Vec3 toVec3(const Vec3d& v) {
  return Vec3{float(v[0]), float(v[1]), float(v[2])};
}

}  // namespace

ProbeSampler::ProbeSampler(const Scene& scene, double spacing) : rate_(scene.output.probeRate) {
  for (const ProbeDesc& desc : scene.probes) {
    Probe p;
    p.kind = desc.kind;
    p.firstPoint = points_.size();
    const std::string& name = desc.name;
    switch (desc.kind) {
      case ProbeKind::Point:
        points_.push_back(toVec3(desc.position));
        p.pointCount = 1;
        for (const char* column :
             {"_pressure_Pa", "_density_kg_m3", "_vx_m_s", "_vy_m_s", "_vz_m_s"})
          columns_.push_back(name + column);
        break;
      case ProbeKind::Level: {
        const Vec3 from = toVec3(desc.from), to = toVec3(desc.to);
        const float length = sph::length(to - from);
        const int intervals = std::max(1, int(std::ceil(length / (0.25 * spacing))));
        p.pointCount = std::size_t(intervals) + 1;
        p.step = length / float(intervals);
        for (int k = 0; k <= intervals; ++k)
          points_.push_back(from + (to - from) * (float(k) / float(intervals)));
        columns_.push_back(name + "_level_m");
        break;
      }
      case ProbeKind::Force:
        p.onWall = !desc.wall.empty();
        for (std::size_t o = 0; o < scene.objects.size(); ++o)
          if (!p.onWall && scene.objects[o].name == desc.object) p.object = o;
        for (std::size_t w = 0; w < scene.walls.size(); ++w)
          if (p.onWall && scene.walls[w].name == desc.wall) p.object = w;
        for (const char* column : {"_fx_N", "_fy_N", "_fz_N"}) columns_.push_back(name + column);
        if (!p.onWall)
          for (const char* column : {"_contact_fx_N", "_contact_fy_N", "_contact_fz_N"})
            columns_.push_back(name + column);
        break;
    }
    probes_.push_back(p);
  }
}

std::vector<double> ProbeSampler::values(const std::vector<PointSums>& sums,
                                         const Forces& forces) const {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> out;
  out.reserve(columns_.size());
  std::vector<float> filled;
  for (const Probe& p : probes_) {
    switch (p.kind) {
      case ProbeKind::Point: {
        const PointValues v = pointValues(sums[p.firstPoint]);
        // In the air a point reads nothing: NaN, not a made-up zero.
        for (float x : {v.pressure, v.density, v.velocity.x, v.velocity.y, v.velocity.z})
          out.push_back(v.wet ? double(x) : nan);
        break;
      }
      case ProbeKind::Level:
        filled.resize(p.pointCount);
        for (std::size_t k = 0; k < p.pointCount; ++k) filled[k] = sums[p.firstPoint + k].filled;
        out.push_back(levelAlong(filled.data(), int(p.pointCount), p.step));
        break;
      case ProbeKind::Force: {
        const auto at = [&](const std::vector<Vec3>& by) {
          return p.object < by.size() ? by[p.object] : Vec3{0, 0, 0};
        };
        const Vec3 f = at(p.onWall ? forces.fluidOnWall : forces.fluidOnObject);
        out.insert(out.end(), {double(f.x), double(f.y), double(f.z)});
        if (p.onWall) break;
        const Vec3 c = at(forces.contactOnObject);
        out.insert(out.end(), {double(c.x), double(c.y), double(c.z)});
        break;
      }
    }
  }
  return out;
}

void ProbeSampler::record(double t, const std::vector<PointSums>& sums, const Forces& forces) {
  if (probes_.empty()) return;
  const std::vector<double> now = values(sums, forces);
  for (;;) {
    const double sampleTime = double(nextSample_) / rate_;
    // A sample time that the state's time rounds onto counts as reached.
    if (sampleTime > t * (1.0 + 1e-12) + 1e-15) break;
    ProbeRow row;
    row.time = sampleTime;
    const bool between = recorded_ && t > lastTime_ && sampleTime > lastTime_;
    const double w = between ? (sampleTime - lastTime_) / (t - lastTime_) : 1.0;
    row.values.resize(now.size());
    for (std::size_t c = 0; c < now.size(); ++c)
      row.values[c] = w >= 1.0 ? now[c] : lastValues_[c] + w * (now[c] - lastValues_[c]);
    rows_.push_back(std::move(row));
    ++nextSample_;
  }
  recorded_ = true;
  lastTime_ = t;
  lastValues_ = now;
}

std::vector<ProbeRow> ProbeSampler::take() {
  std::vector<ProbeRow> out;
  out.swap(rows_);
  return out;
}

void ProbeSampler::save(StateWriter& out) const {
  out.value(std::uint64_t(columns_.size()));
  out.value(std::uint64_t(nextSample_));
  out.value(recorded_);
  out.value(lastTime_);
  out.vector(lastValues_);
  out.value(std::uint64_t(rows_.size()));
  for (const ProbeRow& row : rows_) {
    out.value(row.time);
    out.vector(row.values);
  }
}

void ProbeSampler::load(StateReader& in) {
  if (in.value<std::uint64_t>() != columns_.size()) in.mismatch("its probes");
  nextSample_ = std::size_t(in.value<std::uint64_t>());
  recorded_ = in.value<bool>();
  lastTime_ = in.value<double>();
  lastValues_ = in.vector<double>();
  const std::uint64_t rows = in.value<std::uint64_t>();
  rows_.clear();
  for (std::uint64_t k = 0; k < rows; ++k) {
    ProbeRow row;
    row.time = in.value<double>();
    row.values = in.vector<double>();
    if (row.values.size() != columns_.size()) in.mismatch("a probe row's columns");
    rows_.push_back(std::move(row));
  }
}

}  // namespace sph::sim
