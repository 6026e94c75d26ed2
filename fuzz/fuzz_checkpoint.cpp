// Any bytes as a checkpoint file (sph run --resume): a checkpoint or an InputError naming the
// file. The trailing checksum is made right first, so that the header's JSON behind it is
// fuzzed too, not only the checksum's refusal.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "checkpoint_file.hpp"
#include "sim/state_stream.hpp"
#include "sph/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
  constexpr std::size_t kParts = 24;  // magic and the two lengths
  if (bytes.size() >= kParts + 8) {
    const std::uint64_t sum = sph::sim::fnv1a(bytes.data() + kParts, bytes.size() - kParts - 8);
    std::memcpy(bytes.data() + bytes.size() - 8, &sum, sizeof sum);
  }
  try {
    sph::cli::parseCheckpoint(bytes, "checkpoint_00001.sphck");
  } catch (const sph::InputError&) {
  }
  return 0;
}
