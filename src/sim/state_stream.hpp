// The bytes of a saved simulation state (Simulation::saveState): a header — a magic word, the
// format version, the payload's length and its FNV-1a checksum — then the payload, written and
// read field by field. Plain values are stored as their bytes (the state is read back by the
// same build on the same kind of machine; the version says which), vectors with their length
// first. A reader never reads past what the header promised and never trusts a length it has
// not checked against what is left.
#pragma once

#include <cstdint>
#include <cstring>
#include <istream>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

#include "sph/checksum.hpp"
#include "sph/error.hpp"

namespace sph::sim {

// Bumped whenever what saveState writes changes: a state of another version is refused.
constexpr std::uint32_t kStateFormatVersion = 1;

class StateWriter {
 public:
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>, "only plain values are stored as bytes");
    const auto* bytes = reinterpret_cast<const char*>(&v);
    payload_.insert(payload_.end(), bytes, bytes + sizeof(T));
  }
  template <class T>
  void vector(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>, "only plain values are stored as bytes");
    value(std::uint64_t(v.size()));
    const auto* bytes = reinterpret_cast<const char*>(v.data());
    payload_.insert(payload_.end(), bytes, bytes + v.size() * sizeof(T));
  }
  void text(const std::string& s) {
    value(std::uint64_t(s.size()));
    payload_.insert(payload_.end(), s.begin(), s.end());
  }
  // The header, then the payload. Throws OutputError when the stream fails.
  void finish(std::ostream& out) const;

 private:
  std::vector<char> payload_;
};

class StateReader {
 public:
  // Reads and checks the header and the payload. Throws InputError saying why a stream is not
  // a state this build reads: not a state at all, another format version, cut short, or
  // changed since it was written (the checksum).
  explicit StateReader(std::istream& in);

  template <class T>
  T value() {
    static_assert(std::is_trivially_copyable_v<T>, "only plain values are stored as bytes");
    T v;
    std::memcpy(&v, take(sizeof(T)), sizeof(T));
    return v;
  }
  template <class T>
  std::vector<T> vector() {
    static_assert(std::is_trivially_copyable_v<T>, "only plain values are stored as bytes");
    const std::uint64_t n = value<std::uint64_t>();
    if (n > remaining() / sizeof(T)) fail("a list longer than the state");
    std::vector<T> v(n);
    if (n != 0) std::memcpy(v.data(), take(n * sizeof(T)), n * sizeof(T));
    return v;
  }
  std::string text() {
    const std::uint64_t n = value<std::uint64_t>();
    if (n > remaining()) fail("a text longer than the state");
    const char* at = take(n);
    return std::string(at, at + n);
  }
  // The state was saved from another scene or run: `what` says which part disagrees.
  [[noreturn]] void mismatch(const std::string& what) const;
  // Every field was read: anything left over means the state is not what this build writes.
  void expectEnd() const;

 private:
  std::size_t remaining() const { return payload_.size() - at_; }
  const char* take(std::size_t n);
  [[noreturn]] void fail(const std::string& why) const;
  std::vector<char> payload_;
  std::size_t at_ = 0;
};

using ::sph::fnv1a;  // sph/checksum.hpp

}  // namespace sph::sim
