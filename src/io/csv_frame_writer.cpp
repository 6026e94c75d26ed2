#include "io/csv_frame_writer.hpp"

#include <cinttypes>
#include <cstdio>

namespace sph::io {

void writeCsvFrame(const ParticleFrame& frame, std::ostream& out) {
  out << "id,kind,object,x,y,z,vx,vy,vz,density,pressure,surface\n";
  // %.9g: nine significant digits are enough for every float to read back bit-identical.
  char row[256];
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const float* p = &frame.position[3 * i];
    const float* v = &frame.velocity[3 * i];
    const int len = std::snprintf(
        row, sizeof row, "%" PRIu32 ",%u,%" PRId32 ",%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%u\n",
        frame.id[i], static_cast<unsigned>(frame.kind[i]), frame.object[i], p[0], p[1], p[2], v[0],
        v[1], v[2], frame.density[i], frame.pressure[i],
        i < frame.surface.size() ? unsigned(frame.surface[i]) : 0u);
    out.write(row, len);
  }
}

}  // namespace sph::io
