// Any bytes as the payload of a saved simulation state (Simulation::saveState), under a header
// made right (magic, version, length, checksum), read field by field as the input's first
// bytes choose: every read stays inside the payload or is an InputError.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

#include "sim/state_stream.hpp"
#include "sph/core/vec.hpp"
#include "sph/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::size_t choices = std::min<std::size_t>(data[0], size - 1);
  const std::string plan(reinterpret_cast<const char*>(data) + 1, choices);
  const std::string payload(reinterpret_cast<const char*>(data) + 1 + choices, size - 1 - choices);
  std::string stream("SPHSTATE", 8);
  const std::uint32_t version = sph::sim::kStateFormatVersion, reserved = 0;
  const std::uint64_t length = payload.size(),
                      checksum = sph::sim::fnv1a(payload.data(), payload.size());
  stream.append(reinterpret_cast<const char*>(&version), 4);
  stream.append(reinterpret_cast<const char*>(&reserved), 4);
  stream.append(reinterpret_cast<const char*>(&length), 8);
  stream.append(reinterpret_cast<const char*>(&checksum), 8);
  stream += payload;
  std::istringstream in(stream);
  try {
    sph::sim::StateReader r(in);
    for (char c : plan) {
      switch (static_cast<unsigned char>(c) % 6) {
        case 0:
          r.value<double>();
          break;
        case 1:
          r.value<std::uint8_t>();
          break;
        case 2:
          r.vector<sph::Vec4>();
          break;
        case 3:
          r.vector<std::uint32_t>();
          break;
        case 4:
          r.text();
          break;
        default:
          r.expectEnd();
      }
    }
  } catch (const sph::InputError&) {
  }
  return 0;
}
