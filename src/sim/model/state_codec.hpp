// A State as bytes and back: every field that a step reads, so that a decoded state continues a run with
// the same bits (the payload of the state cache, src/output/state_cache.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "sim/model/model.hpp"
#include "sim/model/state.hpp"

namespace sim {

// The layout version of encode_state(); bump it whenever State gains or changes a field.
// 2: xpbd's carried edge tensions; 3: vbd's BDF2 history; 4: its second step of history; 5: implicit's carried
// velocity change removed
inline constexpr std::uint32_t kStateCodecVersion = 5;

// Every field of `state`, little-endian, doubles as their IEEE bits (exact).
std::string encode_state(const State& state);

// The state encoded in `bytes`, checked against `model` (vertex count, and every carried array sized for
// it or empty). Throws softbody::InputError saying what does not fit (the caller adds the file's name).
State decode_state(std::string_view bytes, const Model& model);

}  // namespace sim
