// What the frame readers share: the error they throw and the frame's shape.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "sph/error.hpp"
#include "sph/frame.hpp"

namespace sph::io {

[[noreturn]] inline void throwBadFrame(const std::filesystem::path& file, const std::string& what) {
  throw InputError(file.string() + ": " + what);
}

// The whole file; throws InputError naming it when it is not a regular file, is over 4 GiB or
// cannot be read.
std::string readFileBytes(const std::filesystem::path& file);

// Sizes every array for `n` particles; surface flags start at 0 for files that lack them.
inline void resizeFrame(ParticleFrame& frame, std::size_t n) {
  frame.id.resize(n);
  frame.position.resize(3 * n);
  frame.velocity.resize(3 * n);
  frame.density.resize(n);
  frame.pressure.resize(n);
  frame.kind.resize(n);
  frame.object.resize(n);
  frame.surface.assign(n, 0);
}

// Kinds outside 0..2 would index past the renderer's and the stages' tables.
inline void requireValidKind(unsigned kind, std::size_t particle,
                             const std::filesystem::path& file) {
  if (kind > static_cast<unsigned>(ParticleKind::Object))
    throwBadFrame(file, "particle " + std::to_string(particle) + " has kind " +
                            std::to_string(kind) + ", expected 0 (fluid), 1 (wall) or 2 (object)");
}

}  // namespace sph::io
