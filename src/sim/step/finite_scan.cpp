// The finite scan: the bits of x − x for every coordinate, OR-ed into one word.
#include "sim/step/finite_scan.hpp"

#include <cstdint>
#include <cstring>

namespace sim {

namespace {

std::uint64_t difference_bits(double coordinate) {
  const double difference = coordinate - coordinate;
  std::uint64_t bits;
  std::memcpy(&bits, &difference, sizeof bits);
  return bits;
}

}  // namespace

bool all_finite(std::span<const softbody::Vec3> values) {
  // x − x is +0 (all bits clear) for every finite x and NaN (some bits set) for NaN and ±∞, so the OR of
  // the bits of x − x over all coordinates is 0 exactly when all are finite: a subtraction and an OR per
  // coordinate, both in SSE2, with no branch.
  const double* coordinates = values.empty() ? nullptr : values.front().data();
  const std::size_t n = 3 * values.size();  // Vec3 is three packed doubles
  static_assert(sizeof(softbody::Vec3) == 3 * sizeof(double));
  // Four independent OR chains (coordinate i into chain i mod 4), so the loop is not held to one OR per
  // cycle by a single accumulator.
  std::uint64_t bits[4] = {0, 0, 0, 0};
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    for (std::size_t lane = 0; lane < 4; ++lane) bits[lane] |= difference_bits(coordinates[i + lane]);
  }
  for (; i < n; ++i) bits[0] |= difference_bits(coordinates[i]);
  const std::uint64_t bits_of_differences = (bits[0] | bits[1]) | (bits[2] | bits[3]);
  return bits_of_differences == 0;
}

}  // namespace sim
