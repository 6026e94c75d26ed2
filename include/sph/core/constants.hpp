// Mathematical constants, once for the whole library.
#pragma once

namespace sph {

constexpr double kPi = 3.14159265358979323846;

}  // namespace sph
