// What a failed file operation throws: the action, the path and the system's reason.
#pragma once

#include <cstring>
#include <filesystem>
#include <string>

#include "sph/error.hpp"

namespace sph::io {

// `error`: the errno of the failure; 0 when the stream failed without a system call (a
// bad_alloc inside it, say).
[[noreturn]] inline void throwFileError(const char* action, const std::filesystem::path& path,
                                        int error) {
  const char* reason = error != 0 ? std::strerror(error) : "unknown error";
  throw OutputError(std::string("cannot ") + action + " '" + path.string() + "': " + reason);
}

}  // namespace sph::io
