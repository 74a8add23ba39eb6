// The chunks of one part of a job that are not yet taken, for threads that help each other: the part's owner takes
// them from the front and any other thread from the back, so the two work apart in memory until they meet.
#pragma once

#include <atomic>
#include <cstdint>

namespace sim {

// [front, back) in one word, so that an owner's and a thief's claims can never take the same chunk.
class ChunkClaims {
 public:
  // Chunks 0 .. chunks − 1 all untaken.
  void reset(int chunks) { range_.store(static_cast<std::uint64_t>(chunks), std::memory_order_relaxed); }
  // The chunk taken (the front one, else the back one), or −1 where none is left.
  int take(bool from_front) {
    std::uint64_t range = range_.load(std::memory_order_relaxed);
    while (true) {
      const auto front = static_cast<int>(range >> 32);
      const auto back = static_cast<int>(range & 0xffffffffu);
      if (front >= back) return -1;
      const std::uint64_t taken = from_front ? pack(front + 1, back) : pack(front, back - 1);
      if (range_.compare_exchange_weak(range, taken, std::memory_order_relaxed)) return from_front ? front : back - 1;
    }
  }

 private:
  static std::uint64_t pack(int front, int back) {
    return (static_cast<std::uint64_t>(front) << 32) | static_cast<std::uint32_t>(back);
  }
  alignas(64) std::atomic<std::uint64_t> range_{0};  // on a line of its own: every claim writes it
};

}  // namespace sim
