// PLY 1.0 (Turk, "The PLY Polygon File Format"): an ASCII header declaring the vertex element and
// its properties, then, in binary, every vertex's properties one after another.
#include "io/ply_writer.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "sph/io/frame_writer.hpp"

namespace sph::io {

// Values are copied from memory as they are, so the host must match binary_little_endian.
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "PLY writer assumes a little-endian host");
static_assert(std::numeric_limits<float>::is_iec559, "PLY float must be IEEE 754");

namespace {

// x y z, vx vy vz, density, pressure (float) + kind (uchar) + object (int) + surface (uchar)
// + id (uint); PLY has no padding, so 42 bytes.
constexpr std::size_t kVertexBytes =
    8 * sizeof(float) + 2 * sizeof(std::uint8_t) + sizeof(std::int32_t) + sizeof(std::uint32_t);

char* put(char* at, const void* value, std::size_t bytes) {
  std::memcpy(at, value, bytes);
  return at + bytes;
}

}  // namespace

void writePly(const ParticleFrame& frame, std::ostream& out) {
  const std::size_t n = frame.size();
  out << "ply\n"
      << "format binary_little_endian 1.0\n"
      << "comment time " << formatDouble(frame.time) << '\n'
      << "comment step " << frame.step << '\n'
      << "element vertex " << n << '\n'
      << "property float x\nproperty float y\nproperty float z\n"
      << "property float vx\nproperty float vy\nproperty float vz\n"
      << "property float density\n"
      << "property float pressure\n"
      << "property uchar kind\n"
      << "property int object\n"
      << "property uchar surface\n"
      << "property uint id\n"
      << "end_header\n";

  // The arrays are stored per field but PLY interleaves per vertex: gather in chunks.
  constexpr std::size_t kChunk = 4096;
  std::vector<char> buffer(std::min(n, kChunk) * kVertexBytes);
  for (std::size_t begin = 0; begin < n; begin += kChunk) {
    const std::size_t end = std::min(n, begin + kChunk);
    char* at = buffer.data();
    for (std::size_t i = begin; i < end; ++i) {
      at = put(at, &frame.position[3 * i], 3 * sizeof(float));
      at = put(at, &frame.velocity[3 * i], 3 * sizeof(float));
      at = put(at, &frame.density[i], sizeof(float));
      at = put(at, &frame.pressure[i], sizeof(float));
      at = put(at, &frame.kind[i], sizeof(std::uint8_t));
      at = put(at, &frame.object[i], sizeof(std::int32_t));
      const std::uint8_t surface = i < frame.surface.size() ? frame.surface[i] : 0;
      at = put(at, &surface, sizeof(std::uint8_t));
      at = put(at, &frame.id[i], sizeof(std::uint32_t));
    }
    out.write(buffer.data(), static_cast<std::streamsize>((end - begin) * kVertexBytes));
  }
}

}  // namespace sph::io
