// Errors the library reports to its callers. The command line maps them to exit codes:
// InputError → 2, SimulationFailure → 3, OutputError → 4.
#pragma once

#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

namespace sph {

// A number as the messages show it: up to 12 significant digits, so that what a user wrote
// (0.001, 1e-300) comes back as written.
inline std::string formatNumber(double value) {
  std::ostringstream out;
  out.precision(12);
  out << value;
  return out.str();
}

// Bad input: the message names the file, the key and what was expected.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writing results failed: a full disk, a read-only or vanished directory. The message names the
// file and the system's reason; whole files already written stay whole.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The simulation left the physical regime (NaN, infinity, density error past the bound).
class SimulationFailure : public std::runtime_error {
 public:
  SimulationFailure(const std::string& message, std::uint64_t step, std::uint32_t particleId,
                    std::string quantity)
      : std::runtime_error(message),
        step_(step),
        particleId_(particleId),
        quantity_(std::move(quantity)) {}
  std::uint64_t step() const { return step_; }
  std::uint32_t particleId() const { return particleId_; }
  const std::string& quantity() const { return quantity_; }

 private:
  std::uint64_t step_;
  std::uint32_t particleId_;
  std::string quantity_;
};

}  // namespace sph
