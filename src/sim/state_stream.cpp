#include "sim/state_stream.hpp"

#include <algorithm>

namespace sph::sim {

namespace {

constexpr char kMagic[8] = {'S', 'P', 'H', 'S', 'T', 'A', 'T', 'E'};

struct Header {
  char magic[8];
  std::uint32_t version;
  std::uint32_t reserved;
  std::uint64_t payloadBytes;
  std::uint64_t checksum;
};

}  // namespace

}  // namespace sph::sim

namespace sph {

std::uint64_t fnv1a(const char* data, std::size_t n, std::uint64_t hash) {
  for (std::size_t k = 0; k < n; ++k) {
    hash ^= static_cast<unsigned char>(data[k]);
    hash *= 1099511628211ull;
  }
  return hash;
}

}  // namespace sph

namespace sph::sim {

void StateWriter::finish(std::ostream& out) const {
  Header header{};
  std::memcpy(header.magic, kMagic, sizeof kMagic);
  header.version = kStateFormatVersion;
  header.payloadBytes = payload_.size();
  header.checksum = fnv1a(payload_.data(), payload_.size());
  out.write(reinterpret_cast<const char*>(&header), sizeof header);
  out.write(payload_.data(), std::streamsize(payload_.size()));
  if (!out) throw OutputError("the simulation's state could not be written");
}

StateReader::StateReader(std::istream& in) {
  Header header{};
  in.read(reinterpret_cast<char*>(&header), sizeof header);
  if (in.gcount() != std::streamsize(sizeof header) ||
      std::memcmp(header.magic, kMagic, sizeof kMagic) != 0)
    fail("not a saved sph simulation state");
  if (header.version != kStateFormatVersion)
    fail("written in state format " + std::to_string(header.version) +
         ", and this build of sph "
         "reads format " +
         std::to_string(kStateFormatVersion) + " only");
  // Read in pieces, so that a corrupted length costs no more memory than the stream holds.
  constexpr std::size_t kPiece = std::size_t(1) << 24;
  while (payload_.size() < header.payloadBytes) {
    const std::size_t want =
        std::size_t(std::min<std::uint64_t>(kPiece, header.payloadBytes - payload_.size()));
    const std::size_t had = payload_.size();
    payload_.resize(had + want);
    in.read(payload_.data() + had, std::streamsize(want));
    if (in.gcount() != std::streamsize(want))
      fail("cut short: " + std::to_string(had + std::size_t(in.gcount())) + " of " +
           std::to_string(header.payloadBytes) + " bytes");
  }
  if (fnv1a(payload_.data(), payload_.size()) != header.checksum)
    fail("corrupted: its checksum does not match its contents");
}

const char* StateReader::take(std::size_t n) {
  if (n > remaining()) fail("cut short inside its fields");
  const char* at = payload_.data() + at_;
  at_ += n;
  return at;
}

void StateReader::fail(const std::string& why) const {
  throw InputError("saved state: " + why);
}

void StateReader::mismatch(const std::string& what) const {
  throw InputError("saved state: not a state of this scene: " + what);
}

void StateReader::expectEnd() const {
  if (remaining() != 0)
    fail(std::to_string(remaining()) + " bytes past the fields this build of sph reads");
}

}  // namespace sph::sim
