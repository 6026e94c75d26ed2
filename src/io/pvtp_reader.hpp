// Reading a parallel frame (.pvtp: one piece a process of a distributed run, vtp_writer.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sph/frame.hpp"

namespace sph::io {

// The pieces' files as the .pvtp lists them, relative to its folder. Throws InputError naming
// `file` when it is not a parallel PolyData file, lists no piece, or a piece outside its folder.
std::vector<std::string> readPvtpPieces(const std::string& bytes,
                                        const std::filesystem::path& file);

// Every piece read and joined into one frame in id order, with the first piece's time. Throws
// InputError naming the piece that cannot be read, or an id two pieces both hold.
ParticleFrame joinPvtpPieces(const std::vector<std::string>& pieces,
                             const std::filesystem::path& file);

}  // namespace sph::io
