#include "distributed/id_order.hpp"

#include <algorithm>

#include "fluid/particles.hpp"

namespace sph::distributed {

std::vector<std::uint32_t> orderById(const std::vector<std::uint32_t>& ids) {
  const std::size_t n = ids.size();
  std::vector<std::uint32_t> order(n), next(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = std::uint32_t(i);
  constexpr std::uint32_t kDigits = 1u << 16;
  std::vector<std::uint32_t> start(kDigits + 1);
  for (int shift : {0, 16}) {
    const auto digit = [&](std::uint32_t i) {
      return ((ids[i] & ~fluid::kGhostBit) >> shift) & (kDigits - 1);
    };
    std::fill(start.begin(), start.end(), 0u);
    for (std::uint32_t i : order) ++start[digit(i) + 1];
    for (std::uint32_t d = 0; d < kDigits; ++d) start[d + 1] += start[d];
    for (std::uint32_t i : order) next[start[digit(i)]++] = i;
    order.swap(next);
  }
  return order;
}

}  // namespace sph::distributed
