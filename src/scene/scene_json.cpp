// Scene files: parse JSON with comments, apply overrides, validate every key, fill defaults.
#include "scene/scene_json.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "core/euler_rotation.hpp"
#include "core/file_kind.hpp"
#include "mesh/generators.hpp"
#include "scene/frame_pattern_check.hpp"
#include "scene/json_text.hpp"
#include "scene/overrides.hpp"
#include "scene/scene_keys.hpp"

namespace scene {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

std::string describe(const json& value) { return describe_json(value); }

// Scene files larger than this are refused before they are read (the largest scene here is 2 kB).
constexpr std::uintmax_t kMaxSceneBytes = 16u << 20;

// Whether `x` lies within the form's bounds.
bool in_range(const Form& form, double x) {
  if (const auto& lo = form.minimum; lo && (lo->exclusive ? x <= lo->value : x < lo->value)) return false;
  if (const auto& hi = form.maximum; hi && (hi->exclusive ? x >= hi->value : x > hi->value)) return false;
  return true;
}

// One JSON object being read against its keys in the table (scene_keys.hpp): takes the forms, ranges and
// defaults from there, and rejects keys the table does not list.
class ObjectReader {
 public:
  ObjectReader(const json& node, std::string path, const fs::path& file, const ObjectKeys& keys)
      : node_(node), path_(std::move(path)), file_(file), keys_(keys) {
    if (!node_.is_object()) fail(path_, "expected an object", &node_);
  }

  [[noreturn]] void fail(const std::string& path, const std::string& expected, const json* got) const {
    std::string message = file_.string() + ": " + (path.empty() ? "(top level)" : message_text(path)) + ": " + expected;
    if (got != nullptr) message += ", got " + describe(*got);
    throw softbody::InputError(message);
  }

  std::string child(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  const Key& spec(const std::string& key) const { return keys_.key(key); }
  bool has(const std::string& key) const {
    spec(key);  // only keys of the table are read
    return node_.contains(key);
  }
  const json& at(const std::string& key) const { return node_.at(key); }

  // The object one of the key's forms reads.
  ObjectReader object(const std::string& key) const {
    return ObjectReader(at(key), child(key), file_, *spec(key).form(FormKind::Object).object);
  }

  double number(const std::string& key) const { return number(key, spec(key).default_value.get<double>()); }
  double number(const std::string& key, double fallback) const {
    if (!has(key)) return fallback;
    return checked_number(at(key), child(key), spec(key).form(FormKind::Number));
  }

  double checked_number(const json& value, const std::string& path, const Form& form) const {
    const std::string words = range_words(form);
    if (!value.is_number()) fail(path, "expected a number" + words, &value);
    const double x = value.get<double>();
    if (!std::isfinite(x) || !in_range(form, x)) fail(path, "expected a finite number" + words, &value);
    // A subnormal number (below 2.2e-308) has lost precision, and quantities derived from it overflow (1/x).
    if (x != 0.0 && !std::isnormal(x))
      fail(path, "expected a finite number" + words + " and 0 or at least 2.2e-308 in magnitude (not subnormal)",
           &value);
    return x;
  }

  int integer(const std::string& key) const { return integer(key, spec(key).default_value.get<int>()); }
  int integer(const std::string& key, int fallback) const {
    if (!has(key)) return fallback;
    const Form& form = spec(key).form(FormKind::Integer);
    const auto lo = static_cast<long long>(form.minimum->value);
    const auto hi = static_cast<long long>(form.maximum->value);
    const json& value = at(key);
    const std::string words = "an integer in " + std::to_string(lo) + ".." + std::to_string(hi);
    if (!value.is_number_integer()) fail(child(key), "expected " + words, &value);
    const auto x = value.get<long long>();
    if (x < lo || x > hi) fail(child(key), "expected " + words, &value);
    return static_cast<int>(x);
  }

  bool boolean(const std::string& key) const {
    if (!has(key)) return spec(key).default_value.get<bool>();
    spec(key).form(FormKind::Boolean);
    if (!at(key).is_boolean()) fail(child(key), "expected true or false", &at(key));
    return at(key).get<bool>();
  }

  std::string string(const std::string& key) const { return string(key, spec(key).default_value.get<std::string>()); }
  std::string string(const std::string& key, const std::string& fallback) const {
    if (!has(key)) return fallback;
    spec(key).form(FormKind::String);
    if (!at(key).is_string() || at(key).get<std::string>().empty()) {
      fail(child(key), "expected a non-empty string", &at(key));
    }
    check_text(key);
    return at(key).get<std::string>();
  }

  // A string within the key's length, and one that names a file without control characters or parts longer
  // than a file name.
  void check_text(const std::string& key) const {
    const Key& k = spec(key);
    const std::string& text = at(key).get_ref<const std::string&>();
    if (k.max_bytes != 0 && text.size() > k.max_bytes) {
      const std::string why = !k.names_file                      ? ""
                              : k.max_bytes == kMaxFileNameBytes ? " (what a file name may hold)"
                                                                 : " (what a path may hold)";
      fail(child(key), "expected at most " + std::to_string(k.max_bytes) + " bytes" + why, &at(key));
    }
    if (!k.names_file) return;
    const auto control = std::find_if(text.begin(), text.end(), [](char c) {
      return static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) == 0x7f;
    });
    if (control != text.end()) {
      fail(child(key), "expected a name without control characters (NUL, line breaks, ...): it names a file", &at(key));
    }
    std::size_t part_start = 0;
    for (std::size_t slash = 0; slash != std::string::npos; part_start = slash + 1) {
      slash = text.find('/', part_start);
      const std::size_t part = (slash == std::string::npos ? text.size() : slash) - part_start;
      if (part > kMaxFileNameBytes) {
        fail(child(key),
             "expected each part between slashes at most " + std::to_string(kMaxFileNameBytes) +
                 " bytes (what a file name may hold), got one of " + std::to_string(part) + " bytes",
             &at(key));
      }
    }
  }

  // The value of `options` named by the key's string (or its default); the names must be the table's choices, in
  // its order, which messages list.
  template <typename Enum>
  Enum choice(const std::string& key, const std::vector<std::pair<std::string, Enum>>& options) const {
    const Key& k = spec(key);
    const std::vector<std::string>& names = k.form(FormKind::Choice).choices;
    for (std::size_t i = 0; i < names.size() || i < options.size(); ++i) {
      if (i >= names.size() || i >= options.size() || names[i] != options[i].first)
        throw std::logic_error("scene key table: the choices of \"" + k.name + "\" differ from the parser's");
    }
    const json& value = has(key) ? at(key) : k.default_value;
    std::string words = "expected one of";
    for (const auto& [name, chosen] : options) {
      if (value.is_string() && value.get_ref<const std::string&>() == name) return chosen;
      words += " \"" + name + "\"";
    }
    fail(child(key), words, &value);
  }

  Vec3 vec3(const std::string& key) const {
    const Key& k = spec(key);
    if (!has(key))
      return Vec3(k.default_value[0].get<double>(), k.default_value[1].get<double>(), k.default_value[2].get<double>());
    const Form& form = k.form(FormKind::Vector);
    const json& value = at(key);
    if (!value.is_array() || value.size() != 3) fail(child(key), "expected an array of 3 numbers", &value);
    Vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = checked_number(value[i], child(key) + "." + std::to_string(i), form);
    return v;
  }

  std::array<float, 3> color(const std::string& key) const {
    const Key& k = spec(key);
    std::array<float, 3> rgb{};
    if (!has(key)) {
      for (int i = 0; i < 3; ++i) rgb[i] = static_cast<float>(k.default_value[i].get<double>());
      return rgb;
    }
    const Form& form = k.form(FormKind::Color);
    const json& value = at(key);
    if (!value.is_array() || value.size() != 3)
      fail(child(key), "expected an RGB array of 3 numbers in [0, 1]", &value);
    for (int i = 0; i < 3; ++i) {
      rgb[i] = static_cast<float>(checked_number(value[i], child(key) + "." + std::to_string(i), form));
    }
    return rgb;
  }

  // Rejects keys the table does not list for this object (typos), naming the first one and the keys it knows.
  void reject_unknown() const {
    std::set<std::string> known;
    for (const Key& k : keys_.keys) known.insert(k.name);
    for (const auto& [key, value] : node_.items()) {
      if (known.count(key) == 0) {
        std::string words = "unknown key (known keys:";
        for (const std::string& k : known) words += " " + k;
        fail(child(key), words + ")", nullptr);
      }
    }
  }

  const fs::path& file() const { return file_; }

 private:
  const json& node_;
  std::string path_;
  const fs::path& file_;
  const ObjectKeys& keys_;
};

// The solver keys `r` gives that its integrator does not read, as notes (not errors: a scene may carry the keys of
// several integrators, switched with --set), e.g. "solver.substeps is not used by rk4 (only by xpbd and vbd)".
void note_unused_solver_keys(const ObjectReader& r, const sim::Solver& solver, std::vector<std::string>& notes) {
  const sim::IntegratorInfo& info = sim::integrator_info(solver.integrator);
  const bool vbd = solver.integrator == sim::IntegratorKind::Vbd;
  const struct {
    const char* key;
    bool used;
    const char* by;
  } keys[] = {{"substeps", info.frame_substeps, "xpbd and vbd"},
              {"iterations", vbd, "vbd"},
              {"impact_phase", vbd, "vbd"},
              {"coarse_space", vbd, "vbd"},
              {"tolerance", solver.integrator == sim::IntegratorKind::Rk45, "rk45"}};
  for (const auto& key : keys) {
    if (key.used || !r.has(key.key)) continue;
    notes.push_back(r.child(key.key) + " is not used by " + std::string(info.name) + " (only by " + key.by + ")");
  }
}

sim::Solver read_solver(const ObjectReader& top, std::vector<std::string>& notes) {
  sim::Solver solver;
  if (!top.has("solver")) return solver;
  const ObjectReader r = top.object("solver");
  std::vector<std::pair<std::string, sim::IntegratorKind>> integrators;
  for (const sim::IntegratorInfo& integrator : sim::kIntegrators) {
    integrators.emplace_back(integrator.name, integrator.kind);
  }
  if (r.has("integrator") && r.at("integrator") == "newton") {
    r.fail(r.child("integrator"),
           "\"newton\" was removed: use \"vbd\", which takes every force implicitly as newton did, at second order, "
           "and was cheaper and more accurate in every case measured (docs/physics/integrators.md)",
           &r.at("integrator"));
  }
  if (r.has("integrator") && r.at("integrator") == "implicit") {
    r.fail(r.child("integrator"),
           "\"implicit\" was removed: use \"vbd\" (every force implicit, second order, no stable-step limit), "
           "which was cheaper and more accurate on every benchmark scene (docs/physics/integrators.md), with "
           "solver.substeps: \"auto\" to let it choose its steps",
           &r.at("integrator"));
  }
  solver.integrator = r.choice<sim::IntegratorKind>("integrator", integrators);
  if (r.has("dt") && r.at("dt").is_string()) {
    if (r.at("dt").get<std::string>() != "auto")
      r.fail(r.child("dt"), "expected a number > 0 or \"auto\"", &r.at("dt"));
    solver.dt_auto = true;
  } else {
    solver.dt_s = r.number("dt");
  }
  // xpbd's substeps per frame interval: a whole number >= 1 or "auto" (sim::Solver::substeps).
  if (r.has("substeps") && r.at("substeps").is_string()) {
    if (r.at("substeps").get<std::string>() != "auto") {
      r.fail(r.child("substeps"), "expected a whole number >= 1 or \"auto\"", &r.at("substeps"));
    }
    solver.substeps_auto = true;
  } else {
    solver.substeps = r.integer("substeps", solver.substeps);
  }
  // vbd's sweeps per step: a whole number >= 1, "converge" or "auto" (sim::SweepControl).
  if (r.has("iterations") && r.at("iterations").is_string()) {
    const std::string choice = r.at("iterations").get<std::string>();
    if (choice != "converge" && choice != "auto") {
      r.fail(r.child("iterations"), "expected a whole number >= 1, \"converge\" or \"auto\"", &r.at("iterations"));
    }
    solver.sweep_control = choice == "auto" ? sim::SweepControl::Auto : sim::SweepControl::Converge;
  } else {
    solver.iterations = r.integer("iterations");
  }
  if (r.has("impact_phase")) solver.impact_phase = r.number("impact_phase", sim::kVbdImpactPhase);
  // vbd's coarse level: cells per body, or "auto" (the default; sim::auto_coarse_cells).
  if (!r.has("coarse_space") || r.at("coarse_space").is_string()) {
    if (r.has("coarse_space") && r.at("coarse_space").get<std::string>() != "auto") {
      r.fail(r.child("coarse_space"), "expected a whole number 0..512 or \"auto\"", &r.at("coarse_space"));
    }
    solver.coarse_space_auto = true;
  } else {
    solver.coarse_space = r.integer("coarse_space", 0);
    solver.coarse_space_auto = false;
  }
  solver.retry = r.boolean("retry");
  solver.tolerance = r.number("tolerance");
  solver.threads = r.integer("threads");
  r.reject_unknown();
  note_unused_solver_keys(r, solver, notes);
  return solver;
}

// The smooth contact's keys, read whatever the contact model, so that --set can switch a scene to smooth.
void read_smooth_contact(const ObjectReader& r, sim::SmoothContact& smooth) {
  smooth.time_constant_s = r.number("time_constant");
  if (r.has("damping_ratio")) smooth.damping_ratio = r.number("damping_ratio", 0.0);
  smooth.slip_speed_m_per_s = r.number("slip_speed");
  smooth.smoothing_m = r.number("smoothing");
}

std::optional<sim::Floor> read_floor(const ObjectReader& top) {
  if (!top.has("floor") || top.at("floor").is_null()) return std::nullopt;
  const ObjectReader r = top.object("floor");
  sim::Floor floor;
  floor.height_m = r.number("height");
  floor.contact = r.choice<sim::FloorContact>("contact", {{"paper", sim::FloorContact::Paper},
                                                          {"friction", sim::FloorContact::Friction},
                                                          {"smooth", sim::FloorContact::Smooth}});
  floor.material.restitution = r.number("restitution");
  floor.material.friction = r.number("friction");
  read_smooth_contact(r, floor.smooth);
  r.reject_unknown();
  return floor;
}

// The keys that belong to one collider shape (besides shape, position, rotation and the contact keys).
const std::vector<std::string>& shape_keys(sim::ColliderShape shape) {
  static const std::vector<std::string> plane{"normal"}, box{"size"}, sphere{"radius"}, capsule{"radius", "length"},
      mesh{"mesh", "scale", "thickness", "cache", "cache_fps"};
  switch (shape) {
    case sim::ColliderShape::Plane: return plane;
    case sim::ColliderShape::Box: return box;
    case sim::ColliderShape::Sphere: return sphere;
    case sim::ColliderShape::Capsule: return capsule;
    case sim::ColliderShape::Mesh: return mesh;
  }
  return plane;
}

// Refuses a key of another shape ("radius" on a box) and asks for each of this shape's keys that has no default.
void check_shape_keys(const ObjectReader& r, sim::ColliderShape shape, const std::string& shape_name) {
  const std::vector<std::string>& own = shape_keys(shape);
  std::string own_words;
  for (const std::string& k : own) own_words += (own_words.empty() ? "\"" : ", \"") + k + "\"";
  for (const char* k : {"normal", "size", "radius", "length", "mesh", "scale", "thickness", "cache", "cache_fps"}) {
    const bool belongs = std::find(own.begin(), own.end(), k) != own.end();
    if (!belongs && r.has(k))
      r.fail(r.child(k), "a " + shape_name + " takes no \"" + k + "\" (its own: " + own_words + ")", nullptr);
    if (belongs && !r.has(k) && r.spec(k).default_value.is_null() && r.spec(k).default_words.empty()) {
      r.fail(r.child(k), "expected it for a " + shape_name + " (" + r.spec(k).description + ")", nullptr);
    }
  }
}

// A collider's shape keys into its geometry, with the rotation and position.
sim::ColliderGeometry read_collider_geometry(const ObjectReader& r) {
  if (!r.has("shape")) {
    r.fail(r.child("shape"), "expected one of \"plane\" \"box\" \"sphere\" \"capsule\" \"mesh\"", nullptr);
  }
  sim::ColliderGeometry g;
  g.shape = r.choice<sim::ColliderShape>("shape", {{"plane", sim::ColliderShape::Plane},
                                                   {"box", sim::ColliderShape::Box},
                                                   {"sphere", sim::ColliderShape::Sphere},
                                                   {"capsule", sim::ColliderShape::Capsule},
                                                   {"mesh", sim::ColliderShape::Mesh}});
  check_shape_keys(r, g.shape, r.at("shape").get<std::string>());
  g.position_m = r.vec3("position");
  g.rotation = softbody::rotation_xyz_degrees(r.vec3("rotation"));
  switch (g.shape) {
    case sim::ColliderShape::Plane: {
      const Vec3 normal = r.vec3("normal");
      if (normal.stableNorm() == 0.0) r.fail(r.child("normal"), "expected a non-zero vector", &r.at("normal"));
      g.plane_normal = normal.stableNormalized();  // exact for tiny components, whose squares would underflow
      break;
    }
    case sim::ColliderShape::Box: {
      const Vec3 size = r.vec3("size");
      if (size.minCoeff() <= 0.0) r.fail(r.child("size"), "expected 3 edge lengths, each > 0", &r.at("size"));
      g.half_size_m = 0.5 * size;
      break;
    }
    case sim::ColliderShape::Sphere: g.radius_m = r.number("radius", 0.0); break;
    case sim::ColliderShape::Capsule:
      g.radius_m = r.number("radius", 0.0);
      g.half_length_m = 0.5 * r.number("length", 0.0);
      break;
    case sim::ColliderShape::Mesh: return g;  // its reach once setup has read the mesh
  }
  g.world_reach_m = sim::world_reach(g);
  return g;
}

// A mesh collider's "cache" (a PC2 file, or a numbered OBJ sequence's pattern, relative to the scene) and
// "cache_fps"; refused beside "keys".
void read_collider_cache(const ObjectReader& r, ColliderMeshSource& source) {
  if (!r.has("cache")) {
    if (r.has("cache_fps")) r.fail(r.child("cache_fps"), "expected only with \"cache\" (a point-cached mesh)", nullptr);
    return;
  }
  if (r.has("keys")) {
    r.fail(r.child("cache"),
           "a collider moves by \"keys\" or by a \"cache\", not both (leave one out: a point cache already holds "
           "the whole motion)",
           nullptr);
  }
  const std::string name = r.string("cache", "");
  const fs::path file = r.file().parent_path() / name;
  source.cache_fps = r.has("cache_fps") ? r.number("cache_fps", 0.0) : 0.0;
  if (name.find('%') != std::string::npos) {  // a numbered mesh sequence: its folder must exist
    if (!is_frame_pattern(file.filename().string(), ".obj")) {
      r.fail(r.child("cache"),
             "expected a numbered OBJ sequence's file name with one frame number conversion such as "
             "collider_0_%04d.obj (%d, %4d or %04d; '%%' for a '%'), or a .pc2 file",
             &r.at("cache"));
    }
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    if (const std::string words = softbody::non_regular_file_words(folder); words != "is a directory") {
      r.fail(r.child("cache"), "the folder " + folder.string() + " of the numbered sequence " + words, nullptr);
    }
    source.cache_file = file;
    source.cache_sequence = true;
    return;
  }
  if (fs::path(name).extension() != ".pc2") {
    r.fail(r.child("cache"),
           "expected a point cache file ending in .pc2, or a numbered OBJ sequence such as collider_0_%04d.obj, "
           "relative to the scene",
           &r.at("cache"));
  }
  if (const std::string words = softbody::non_regular_file_words(file); !words.empty()) {
    r.fail(r.child("cache"),
           "point cache " + file.string() + " " + words + " (expected a .pc2 file path relative to the scene)",
           nullptr);
  }
  source.cache_file = file;
}

// A mesh collider's "mesh" (a file relative to the scene, or a generator), "scale" and "thickness".
ColliderMeshSource read_collider_mesh(const ObjectReader& r, std::size_t index) {
  ColliderMeshSource source;
  source.collider = index;
  source.mesh = r.string("mesh", "");  // required: check_shape_keys asked for it
  source.scale = r.number("scale");
  source.thickness_m = r.number("thickness");
  read_collider_cache(r, source);
  if (mesh::names_generator(source.mesh)) {
    if (const std::string error = mesh::generator_spec_error(source.mesh); !error.empty()) {
      r.fail(r.child("mesh"), error, nullptr);
    }
    return source;
  }
  const fs::path file = r.file().parent_path() / source.mesh;
  if (const std::string words = softbody::non_regular_file_words(file); !words.empty()) {
    r.fail(r.child("mesh"),
           "mesh file " + file.string() + " " + words +
               " (expected a mesh file path relative to the scene, or a generator: icosphere:L, cube:N)",
           nullptr);
  }
  source.mesh_file = file;
  return source;
}

// "keys" and "interpolation": a keyframed collider's motion (none: static). A key's position and rotation left out
// take the collider's own; its times must increase.
sim::ColliderMotion read_collider_motion(const ObjectReader& r) {
  sim::ColliderMotion motion;
  motion.interpolation = r.choice<sim::KeyInterpolation>(
      "interpolation", {{"linear", sim::KeyInterpolation::Linear}, {"smooth", sim::KeyInterpolation::Smooth}});
  if (!r.has("keys")) {
    if (r.has("interpolation"))
      r.fail(r.child("interpolation"), "expected only with \"keys\" (a moving collider)", nullptr);
    return motion;
  }
  const json& list = r.at("keys");
  if (!list.is_array() || list.empty()) {
    r.fail(r.child("keys"), "expected an array of at least one key {\"time\": t, \"position\": [x, y, z], ...}", &list);
  }
  const ObjectKeys& keys = *r.spec("keys").form(FormKind::ObjectList).object;
  const Vec3 position = r.vec3("position"), rotation = r.vec3("rotation");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const ObjectReader k(list[i], r.child("keys") + "." + std::to_string(i), r.file(), keys);
    if (!k.has("time")) k.fail(k.child("time"), "expected the key's time [s]", nullptr);
    sim::ColliderKey key;
    key.time_s = k.number("time", 0.0);
    if (i > 0 && !(key.time_s > motion.keys.back().time_s)) {
      k.fail(k.child("time"),
             "expected a time later than the key before's (" + short_number(motion.keys.back().time_s) +
                 " s): the keys' times must increase",
             &k.at("time"));
    }
    key.position_m = k.has("position") ? k.vec3("position") : position;
    key.rotation = sim::Quat(softbody::rotation_xyz_degrees(k.has("rotation") ? k.vec3("rotation") : rotation));
    key.scale = k.number("scale");
    k.reject_unknown();
    motion.keys.push_back(key);
  }
  return motion;
}

// A mesh collider's keys move and turn it but do not scale it (its triangles are scaled once, by "scale").
void refuse_scaling_keys(const ObjectReader& r, const sim::ColliderMotion& motion) {
  for (std::size_t i = 0; i < motion.keys.size(); ++i) {
    if (motion.keys[i].scale != 1.0) {
      const std::string key = r.child("keys") + "." + std::to_string(i) + ".scale";
      r.fail(key,
             "expected 1: a mesh collider's keys move and turn it but cannot scale it (use the collider's \"scale\")",
             nullptr);
    }
  }
}

// A collider: its shape, and the floor's contact keys, each left out taking the floor's value.
// A mesh collider's file goes to `meshes`.
sim::Collider read_collider(const json& node, std::size_t index, const fs::path& file, const ObjectKeys& keys,
                            const sim::Floor& floor, std::vector<ColliderMeshSource>& meshes) {
  const ObjectReader r(node, "colliders." + std::to_string(index), file, keys);
  sim::Collider collider;
  collider.geometry = read_collider_geometry(r);
  if (collider.geometry.shape == sim::ColliderShape::Mesh) meshes.push_back(read_collider_mesh(r, index));
  collider.motion = read_collider_motion(r);
  if (collider.geometry.shape == sim::ColliderShape::Mesh) refuse_scaling_keys(r, collider.motion);
  collider.contact = r.has("contact")
                         ? r.choice<sim::FloorContact>("contact", {{"paper", sim::FloorContact::Paper},
                                                                   {"friction", sim::FloorContact::Friction},
                                                                   {"smooth", sim::FloorContact::Smooth}})
                         : floor.contact;
  collider.material = floor.material;
  collider.material.restitution = r.number("restitution", floor.material.restitution);
  collider.material.friction = r.number("friction", floor.material.friction);
  collider.smooth = floor.smooth;
  collider.smooth.time_constant_s = r.number("time_constant", floor.smooth.time_constant_s);
  collider.smooth.damping_ratio = r.number("damping_ratio", floor.smooth.damping_ratio);
  collider.smooth.slip_speed_m_per_s = r.number("slip_speed", floor.smooth.slip_speed_m_per_s);
  collider.smooth.smoothing_m = r.number("smoothing", floor.smooth.smoothing_m);
  r.reject_unknown();
  return collider;
}

// "colliders": at least one; the floor (or, without one, a floor's defaults) gives the contact keys left out.
std::vector<sim::Collider> read_colliders(const ObjectReader& top, const std::optional<sim::Floor>& floor,
                                          std::vector<ColliderMeshSource>& meshes) {
  if (!top.has("colliders")) return {};
  const json& list = top.at("colliders");
  if (!list.is_array() || list.empty()) {
    top.fail("colliders", "expected an array of at least one collider (leave the key out for none)", &list);
  }
  const ObjectKeys& keys = *top.spec("colliders").form(FormKind::ObjectList).object;
  const sim::Floor defaults = floor ? *floor : sim::Floor{};
  std::vector<sim::Collider> colliders;
  for (std::size_t i = 0; i < list.size(); ++i) {
    colliders.push_back(read_collider(list[i], i, top.file(), keys, defaults, meshes));
  }
  return colliders;
}

std::string read_mesh_spec(const ObjectReader& r, Body& body) {
  const std::string spec = r.string("mesh");
  if (mesh::names_generator(spec)) {
    if (const std::string error = mesh::generator_spec_error(spec); !error.empty()) {
      r.fail(r.child("mesh"), error, nullptr);
    }
    return spec;
  }
  const fs::path file = r.file().parent_path() / spec;
  if (const std::string words = softbody::non_regular_file_words(file); !words.empty()) {
    r.fail(r.child("mesh"),
           "mesh file " + file.string() + " " + words +
               " (expected a mesh file path relative to the scene, "
               "or a generator: icosphere:L, cube:N)",
           nullptr);
  }
  body.mesh_file = file;
  return spec;
}

// True when `key` is given as an object (an intent) rather than its number.
bool given_as_object(const ObjectReader& r, const std::string& key) { return r.has(key) && r.at(key).is_object(); }

// "stiffness": N/m, or {"youngs": Pa, "thickness": m} or {"frequency": Hz}.
void read_stiffness(const ObjectReader& body_reader, Body& body) {
  if (!given_as_object(body_reader, "stiffness")) {
    body.stiffness_N_per_m = body_reader.number("stiffness");
    return;
  }
  const ObjectReader r = body_reader.object("stiffness");
  sim::StiffnessIntent intent;
  intent.youngs_Pa = r.number("youngs", 0.0);
  intent.thickness_m = r.number("thickness");
  intent.frequency_Hz = r.number("frequency", 0.0);
  if ((intent.youngs_Pa > 0.0) == (intent.frequency_Hz > 0.0)) {
    r.fail(body_reader.child("stiffness"),
           "expected exactly one of \"youngs\" (Pa, with \"thickness\" in m) or \"frequency\" (Hz)", nullptr);
  }
  r.reject_unknown();
  body.intent.stiffness = intent;
}

// "damping": N·s/m, or {"ratio": ζ} (fraction of critical damping of the breathing mode).
void read_damping(const ObjectReader& body_reader, Body& body) {
  if (!given_as_object(body_reader, "damping")) {
    body.damping_N_s_per_m = body_reader.number("damping");
    return;
  }
  const ObjectReader r = body_reader.object("damping");
  if (!r.has("ratio")) r.fail(r.child("ratio"), "expected a damping ratio >= 0 (1: critical)", nullptr);
  body.intent.damping_ratio = r.number("ratio", 0.0);
  r.reject_unknown();
}

// "pressure": nRT in J, or {"inflation": f, "start": "equilibrium" | "rest"}.
void read_pressure(const ObjectReader& body_reader, Body& body) {
  if (!given_as_object(body_reader, "pressure")) {
    body.pressure_J = body_reader.number("pressure");
    return;
  }
  const ObjectReader r = body_reader.object("pressure");
  sim::PressureIntent intent;
  intent.inflation = r.number("inflation");
  intent.start_at_equilibrium = r.choice<bool>("start", {{"equilibrium", true}, {"rest", false}});
  r.reject_unknown();
  body.intent.pressure = intent;
}

// "repair": true | false, or {"degenerate", "holes": booleans (default true), "parts": "union" (default) | "keep" |
// "largest"}.
void read_repair(const ObjectReader& body_reader, Body& body) {
  if (!body_reader.has("repair")) return;
  const json& value = body_reader.at("repair");
  if (value.is_boolean()) {
    if (value.get<bool>()) body.repair = mesh::full_repair();
    return;
  }
  if (!value.is_object()) {
    body_reader.fail(body_reader.child("repair"), "expected true, false or an object of repair steps", &value);
  }
  const ObjectReader r = body_reader.object("repair");
  mesh::RepairOptions repair = mesh::full_repair();
  repair.degenerate = r.boolean("degenerate");
  repair.holes = r.boolean("holes");
  repair.parts = r.choice<mesh::PartsPolicy>("parts", {{"union", mesh::PartsPolicy::Union},
                                                       {"keep", mesh::PartsPolicy::Keep},
                                                       {"largest", mesh::PartsPolicy::Largest}});
  r.reject_unknown();
  body.repair = repair;
}

// "resolution": N (the proxy's vertex count) or {"edge_length": L} (its edge length, metres once placed);
// null as if left out.
void read_resolution(const ObjectReader& r, Body& body) {
  if (!r.has("resolution") || r.at("resolution").is_null()) return;  // null: simulate the mesh as it is
  const json& value = r.at("resolution");
  if (value.is_object()) {
    const ObjectReader inner = r.object("resolution");
    if (!inner.has("edge_length")) {
      inner.fail(r.child("resolution"), "expected {\"edge_length\": L} with L > 0 in metres", &value);
    }
    body.resolution_edge_length_m = inner.number("edge_length", 0.0);
    inner.reject_unknown();
    return;
  }
  body.resolution_vertices = r.integer("resolution", 0);
}

// "bending": k_b in N/m, or {"ratio": r} (k_b = r k, relative to the edge springs).
void read_bending(const ObjectReader& body_reader, Body& body) {
  if (!given_as_object(body_reader, "bending")) {
    body.bending_N_per_m = body_reader.number("bending");
    return;
  }
  const ObjectReader r = body_reader.object("bending");
  if (!r.has("ratio"))
    r.fail(r.child("ratio"), "expected a ratio >= 0 of the bending links' stiffness to the edges'", nullptr);
  body.intent.bending_ratio = r.number("ratio", 0.0);
  r.reject_unknown();
}

Body read_body(const json& node, const std::string& path, const fs::path& file, const ObjectKeys& keys) {
  const ObjectReader r(node, path, file, keys);
  Body body;
  body.mesh = read_mesh_spec(r, body);
  body.position_m = r.vec3("position");
  body.rotation_deg = r.vec3("rotation");
  body.scale = r.number("scale");
  body.velocity_m_per_s = r.vec3("velocity");
  body.mass_kg = r.number("mass");
  read_stiffness(r, body);
  read_damping(r, body);
  read_pressure(r, body);
  read_bending(r, body);
  body.split = r.boolean("split");
  body.self_collision = r.boolean("self_collision");
  read_repair(r, body);
  read_resolution(r, body);
  body.color = r.color("color");
  body.pattern = r.choice<Pattern>(
      "pattern", {{"none", Pattern::None}, {"checker", Pattern::Checker}, {"stripes", Pattern::Stripes}});
  r.reject_unknown();
  return body;
}

std::vector<Body> read_bodies(const ObjectReader& top) {
  if (!top.has("bodies")) top.fail("bodies", "expected an array of at least one body", nullptr);
  const json& list = top.at("bodies");
  if (!list.is_array() || list.empty()) top.fail("bodies", "expected an array of at least one body", &list);
  const ObjectKeys& body_keys = *top.spec("bodies").form(FormKind::ObjectList).object;
  std::vector<Body> bodies;
  for (std::size_t i = 0; i < list.size(); ++i) {
    bodies.push_back(read_body(list[i], "bodies." + std::to_string(i), top.file(), body_keys));
  }
  return bodies;
}

sim::BodyContact read_collisions(const ObjectReader& top) {
  sim::BodyContact collisions;
  if (!top.has("collisions")) return collisions;
  const ObjectReader r = top.object("collisions");
  collisions.contact = r.choice<sim::BodyContactModel>(
      "contact", {{"impulse", sim::BodyContactModel::Impulse}, {"smooth", sim::BodyContactModel::Smooth}});
  collisions.material.restitution = r.number("restitution");
  collisions.material.friction = r.number("friction");
  collisions.push_speed_m_per_s = r.number("push_speed");
  read_smooth_contact(r, collisions.smooth);
  r.reject_unknown();
  return collisions;
}

int even_size(const ObjectReader& r, const std::string& key) {
  const int size = r.integer(key);
  if (size % r.spec(key).form(FormKind::Integer).multiple_of != 0)
    r.fail(r.child(key), "expected an even number of pixels (video encoders need it)", &r.at(key));
  return size;
}

// 1 to 64 frame numbers (>= 0, each once), sorted: the contact sheet's tiles in reading order.
std::vector<int> frame_list(const ObjectReader& r, const std::string& key) {
  const json& value = r.at(key);
  if (value.empty() || value.size() > 64) r.fail(r.child(key), "expected a list of 1 to 64 frame numbers", &value);
  std::vector<int> frames;
  for (const json& item : value) {
    if (!item.is_number_integer() || item.get<long long>() < 0 || item.get<long long>() > 1000000000) {
      r.fail(r.child(key), "expected frame numbers (integers >= 0)", &item);
    }
    frames.push_back(item.get<int>());
  }
  std::sort(frames.begin(), frames.end());
  if (std::adjacent_find(frames.begin(), frames.end()) != frames.end()) {
    r.fail(r.child(key), "expected each frame once", &value);
  }
  return frames;
}

RenderSettings read_render(const ObjectReader& top) {
  RenderSettings render;
  if (!top.has("render")) return render;
  const ObjectReader r = top.object("render");
  render.width_px = even_size(r, "width");
  render.height_px = even_size(r, "height");
  render.msaa = r.integer("msaa");
  const std::vector<long long>& excluded = r.spec("msaa").form(FormKind::Integer).excluded;
  if (std::find(excluded.begin(), excluded.end(), render.msaa) != excluded.end())
    r.fail("render.msaa", "expected 1, 2 or 4 samples", &r.at("msaa"));
  render.shadows = r.boolean("shadows");
  render.background = r.color("background");
  if (r.has("figure_frames") && r.at("figure_frames").is_array()) {
    render.figure_frame_list = frame_list(r, "figure_frames");
    render.figure_frames = static_cast<int>(render.figure_frame_list.size());
  } else {
    render.figure_frames = r.integer("figure_frames");
  }
  render.backend = r.choice<GlBackend>(
      "backend", {{"auto", GlBackend::Auto}, {"egl", GlBackend::Egl}, {"osmesa", GlBackend::OsMesa}});
  r.reject_unknown();
  return render;
}

Camera read_camera(const ObjectReader& top) {
  Camera camera;
  if (!top.has("camera")) return camera;
  const ObjectReader r = top.object("camera");
  camera.given = true;
  camera.position_m = r.vec3("position");
  camera.target_m = r.vec3("target");
  camera.up = r.vec3("up");
  camera.fov_deg = r.number("fov");
  if ((camera.target_m - camera.position_m).norm() == 0.0)
    r.fail("camera.target", "expected a point other than camera.position", nullptr);
  if (camera.up.norm() == 0.0 || camera.up.cross(camera.target_m - camera.position_m).norm() == 0.0) {
    r.fail("camera.up", "expected a non-zero vector not parallel to the view direction", nullptr);
  }
  r.reject_unknown();
  return camera;
}

Light read_light(const ObjectReader& top) {
  Light light;
  if (!top.has("light")) return light;
  const ObjectReader r = top.object("light");
  light.direction = r.vec3("direction");
  if (light.direction.norm() == 0.0) r.fail("light.direction", "expected a non-zero vector", nullptr);
  light.color = r.color("color");
  light.ambient = static_cast<float>(r.number("ambient"));
  r.reject_unknown();
  return light;
}

// "limits": what a mesh file (mesh/mesh_limits.hpp) and the whole scene (setup/scene_totals.hpp) may hold,
// raised for large meshes and many bodies.
void read_limits(const ObjectReader& top, Scene& s) {
  s.totals.max_vertices =
      top.spec("limits").form(FormKind::Object).object->key("max_total_vertices").default_value.get<long long>();
  s.totals.max_triangles =
      top.spec("limits").form(FormKind::Object).object->key("max_total_triangles").default_value.get<long long>();
  if (!top.has("limits")) return;
  const ObjectReader r = top.object("limits");
  s.limits.max_triangles = r.integer("max_triangles");
  s.limits.max_vertices = r.integer("max_vertices");
  s.limits.max_file_bytes = static_cast<std::uintmax_t>(r.integer("max_file_mb")) << 20;
  s.totals.max_vertices = r.integer("max_total_vertices");
  s.totals.max_triangles = r.integer("max_total_triangles");
  r.reject_unknown();
}

Output read_output(const ObjectReader& top, const std::string& name) {
  Output output;
  output.dir = fs::path("out") / name;
  if (!top.has("output")) return output;
  const ObjectReader r = top.object("output");
  output.dir = r.string("dir", output.dir.string());
  output.pattern = r.string("pattern");
  // Checked for every command, not only render: a scene is valid or not whatever is done with it.
  check_frame_pattern(output.pattern, top.file().string());
  r.reject_unknown();
  return output;
}

}  // namespace

json parse_scene_text(const std::string& text, const fs::path& file) {
  return parse_json_limited(text, file.string(), /*comments=*/true);
}

Scene scene_from_json(const json& document, const fs::path& file) {
  const ObjectReader top(document, "", file, scene_keys());
  Scene s;
  s.source = file;
  top.string("$schema", "");  // for editors: checked to be a string, otherwise ignored
  s.name = top.string("name", fs::path(file).stem().string());
  const std::vector<std::string>& refused = top.spec("name").refused;
  if (s.name.find_first_of("/\\") != std::string::npos ||
      std::find(refused.begin(), refused.end(), s.name) != refused.end()) {
    top.fail("name", "expected a name without slashes, other than \".\" and \"..\" (it names the folder out/NAME)",
             &top.at("name"));
  }
  s.duration_s = top.number("duration");
  s.fps = top.integer("fps");
  s.solver = read_solver(top, s.notes);
  s.gravity_m_per_s2 = top.vec3("gravity");
  s.floor = read_floor(top);
  s.colliders = read_colliders(top, s.floor, s.collider_meshes);
  read_limits(top, s);
  s.bodies = read_bodies(top);
  s.collisions = read_collisions(top);
  s.render = read_render(top);
  s.camera = read_camera(top);
  s.light = read_light(top);
  s.output = read_output(top, s.name);
  json simulation = document;
  for (const char* key : {"$schema", "name", "render", "camera", "light", "output", "limits"}) simulation.erase(key);
  // Invalid UTF-8 (possible in --set values, which are taken as bytes) is replaced (U+FFFD), not thrown about;
  // valid text dumps exactly as before.
  s.simulation_json = simulation.dump(-1, ' ', false, json::error_handler_t::replace);
  top.reject_unknown();
  return s;
}

Scene load_scene(const fs::path& file, const std::vector<std::string>& overrides) {
  softbody::require_regular_file(file, kMaxSceneBytes, "scene file", "");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw softbody::InputError(file.string() + ": cannot open the scene file");
  std::stringstream text;
  text << in.rdbuf();
  json document = parse_scene_text(text.str(), file);
  for (const std::string& assignment : overrides) apply_override(document, assignment);
  return scene_from_json(document, file);
}

}  // namespace scene
