// Encoding and decoding a State field by field.
#include "sim/model/state_codec.hpp"

#include <bit>
#include <cstring>
#include <type_traits>
#include <vector>

#include "core/errors.hpp"

namespace sim {
namespace {

static_assert(std::endian::native == std::endian::little, "the state cache is little-endian");

class Writer {
 public:
  template <class T>
  void scalar(T value) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  template <class T>
  void array(const T* data, std::size_t count) {
    scalar<std::uint64_t>(count);
    if (count > 0) bytes_.append(reinterpret_cast<const char*>(data), count * sizeof(T));
  }
  void vectors(const std::vector<Vec3>& v) { array(v.empty() ? nullptr : v.front().data(), 3 * v.size()); }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  template <class T>
  T scalar(const char* what) {
    T value;
    take(&value, sizeof value, what);
    return value;
  }
  // An array of `T`: its count first; `expected` says which counts are valid (0 is always).
  template <class T>
  std::vector<T> array(const char* what, std::uint64_t expected) {
    const auto count = scalar<std::uint64_t>(what);
    if (count != 0 && count != expected) {
      throw softbody::InputError(std::string(what) + " holds " + std::to_string(count) + " values, expected " +
                                 std::to_string(expected) + " (a state of another model)");
    }
    std::vector<T> values(count);
    take(values.data(), count * sizeof(T), what);
    return values;
  }
  std::vector<Vec3> vectors(const char* what, std::size_t vertices) {
    const std::vector<double> flat = array<double>(what, 3 * vertices);
    std::vector<Vec3> v(flat.size() / 3);
    if (!flat.empty()) std::memcpy(v.front().data(), flat.data(), flat.size() * sizeof(double));
    return v;
  }
  void expect_end() const {
    if (offset_ != bytes_.size())
      throw softbody::InputError("state has " + std::to_string(bytes_.size() - offset_) +
                                 " bytes after its last field");
  }

 private:
  void take(void* out, std::size_t size, const char* what) {
    if (bytes_.size() - offset_ < size) throw softbody::InputError(std::string("state ends inside ") + what);
    if (size > 0) std::memcpy(out, bytes_.data() + offset_, size);
    offset_ += size;
  }
  std::string_view bytes_;
  std::size_t offset_ = 0;
};

}  // namespace

std::string encode_state(const State& state) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is three packed doubles");
  Writer w;
  w.vectors(state.x);
  w.vectors(state.v);
  w.scalar(state.time_s);
  w.scalar<std::int64_t>(state.steps);
  w.scalar<std::int64_t>(state.rejected_steps);
  w.scalar<std::int64_t>(state.retried_steps);
  w.scalar<std::int32_t>(state.retry_substeps);
  w.scalar(state.next_dt_s);
  w.scalar(state.last_dt_s);
  w.vectors(state.carry.acceleration);
  w.array(state.carry.edge_tension_N.data(), state.carry.edge_tension_N.size());
  w.vectors(state.carry.previous_x);
  w.vectors(state.carry.previous_v);
  w.scalar(state.carry.previous_dt_s);
  w.vectors(state.carry.older_x);
  w.vectors(state.carry.older_v);
  w.scalar(state.carry.older_dt_s);
  w.scalar(state.carry.previous_error);
  w.scalar<std::uint8_t>(state.carry.rejected_last ? 1 : 0);
  w.array(state.coasting.data(), state.coasting.size());
  w.array(state.guard.budget_J.data(), state.guard.budget_J.size());
  w.scalar<std::int32_t>(state.guard.steps_since_full_check);
  return w.take();
}

State decode_state(std::string_view bytes, const Model& model) {
  const std::size_t n = model.vertex_count();
  Reader r(bytes);
  State state;
  state.x = r.vectors("positions", n);
  state.v = r.vectors("velocities", n);
  if (state.x.size() != n || state.v.size() != n) {
    throw softbody::InputError("state has " + std::to_string(state.x.size()) + " vertices, the model " +
                               std::to_string(n));
  }
  state.time_s = r.scalar<double>("time");
  state.steps = r.scalar<std::int64_t>("step count");
  state.rejected_steps = r.scalar<std::int64_t>("rejected step count");
  state.retried_steps = r.scalar<std::int64_t>("retried step count");
  state.retry_substeps = r.scalar<std::int32_t>("substeps");
  state.next_dt_s = r.scalar<double>("next dt");
  state.last_dt_s = r.scalar<double>("last dt");
  state.carry.acceleration = r.vectors("carried acceleration", n);
  std::size_t constraints = 0;
  for (const Body& body : model.bodies) constraints += body.constraints.size();
  state.carry.edge_tension_N = r.array<double>("carried edge tensions", constraints);
  state.carry.previous_x = r.vectors("BDF2 history positions", n);
  state.carry.previous_v = r.vectors("BDF2 history velocities", n);
  state.carry.previous_dt_s = r.scalar<double>("BDF2 history step");
  state.carry.older_x = r.vectors("BDF2 older history positions", n);
  state.carry.older_v = r.vectors("BDF2 older history velocities", n);
  state.carry.older_dt_s = r.scalar<double>("BDF2 older history step");
  state.carry.previous_error = r.scalar<double>("step-size controller error");
  state.carry.rejected_last = r.scalar<std::uint8_t>("step-size controller flag") != 0;
  const auto coasting_count = r.scalar<std::uint64_t>("coasting vertices");
  if (coasting_count > n) throw softbody::InputError("state lists more coasting vertices than the model has");
  state.coasting.resize(coasting_count);
  for (int& vertex : state.coasting) {
    vertex = r.scalar<std::int32_t>("coasting vertices");
    if (vertex < 0 || static_cast<std::size_t>(vertex) >= n)
      throw softbody::InputError("state names a vertex outside the model");
  }
  state.guard.budget_J = r.array<double>("guard budget", model.bodies.size());
  state.guard.steps_since_full_check = r.scalar<std::int32_t>("guard counter");
  r.expect_end();
  if (state.retry_substeps < 1) throw softbody::InputError("state has a substep count below 1");
  return state;
}

}  // namespace sim
