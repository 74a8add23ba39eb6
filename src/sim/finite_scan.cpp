// The finite scan: exponent bits of every double, OR-ed into one flag.
#include "sim/finite_scan.hpp"

#include <cstdint>
#include <cstring>

namespace sim {

bool all_finite(std::span<const softbody::Vec3> values) {
  constexpr std::uint64_t kExponent = 0x7ff0000000000000ULL;  // all ones: NaN or ±∞
  const double* coordinates = values.empty() ? nullptr : values.front().data();
  const std::size_t n = 3 * values.size();  // Vec3 is three packed doubles
  static_assert(sizeof(softbody::Vec3) == 3 * sizeof(double));
  std::uint64_t non_finite = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t bits;
    std::memcpy(&bits, coordinates + i, sizeof bits);
    non_finite |= static_cast<std::uint64_t>((bits & kExponent) == kExponent);
  }
  return non_finite == 0;
}

}  // namespace sim
