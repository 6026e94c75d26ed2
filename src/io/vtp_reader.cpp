// Reads the particle frames vtp_writer.cpp writes.
#include <cstdint>
#include <string>

#include "io/frame_reader_support.hpp"
#include "io/vtp_document.hpp"
#include "sph/io/frame_reader.hpp"

namespace sph::io {

ParticleFrame readVtp(const std::string& bytes, const std::filesystem::path& file) {
  const VtpDocument vtp(bytes, file);
  const std::uint64_t n = vtp.pieceCount("NumberOfPoints");
  ParticleFrame frame;
  resizeFrame(frame, n);
  frame.time = vtp.time();
  vtp.read("Points", "Float32", 3, n, frame.position.data());
  vtp.read("velocity", "Float32", 3, n, frame.velocity.data());
  vtp.read("density", "Float32", 1, n, frame.density.data());
  vtp.read("pressure", "Float32", 1, n, frame.pressure.data());
  vtp.read("kind", "UInt8", 1, n, frame.kind.data());
  vtp.read("object", "Int32", 1, n, frame.object.data());
  vtp.read("id", "UInt32", 1, n, frame.id.data());
  if (vtp.has("surface")) vtp.read("surface", "UInt8", 1, n, frame.surface.data());
  if (vtp.has("torn")) {
    frame.torn.resize(n);
    vtp.read("torn", "UInt8", 1, n, frame.torn.data());
  }
  for (std::size_t i = 0; i < n; ++i) requireValidKind(frame.kind[i], i, file);
  return frame;
}

}  // namespace sph::io
