// The checksum of sph's own files (checkpoints, saved simulation states).
#pragma once

#include <cstddef>
#include <cstdint>

namespace sph {

// FNV-1a, 64 bits: a checksum (not a defence against tampering). `hash` carries a checksum on
// over more bytes: fnv1a(b, m, fnv1a(a, n)) is the checksum of a then b.
constexpr std::uint64_t kFnv1aStart = 14695981039346656037ull;
std::uint64_t fnv1a(const char* data, std::size_t n, std::uint64_t hash = kFnv1aStart);

}  // namespace sph
