// The finite scan: the bits of x − x for every coordinate, OR-ed into one word.
#include "sim/finite_scan.hpp"

#include <cstdint>
#include <cstring>

namespace sim {

bool all_finite(std::span<const softbody::Vec3> values) {
  // x − x is +0 (all bits clear) for every finite x and NaN (some bits set) for NaN and ±∞, so the OR of
  // the bits of x − x over all coordinates is 0 exactly when all are finite: a subtraction and an OR per
  // coordinate, both in SSE2, with no branch.
  const double* coordinates = values.empty() ? nullptr : values.front().data();
  const std::size_t n = 3 * values.size();  // Vec3 is three packed doubles
  static_assert(sizeof(softbody::Vec3) == 3 * sizeof(double));
  std::uint64_t bits_of_differences = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double difference = coordinates[i] - coordinates[i];
    std::uint64_t bits;
    std::memcpy(&bits, &difference, sizeof bits);
    bits_of_differences |= bits;
  }
  return bits_of_differences == 0;
}

}  // namespace sim
