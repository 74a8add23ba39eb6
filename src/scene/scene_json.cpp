// Scene files: parse JSON with comments, apply overrides, validate every key, fill defaults.
#include "scene/scene_json.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "core/file_kind.hpp"
#include "mesh/generators.hpp"
#include "scene/frame_pattern_check.hpp"
#include "scene/json_text.hpp"
#include "scene/overrides.hpp"

namespace scene {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

std::string describe(const json& value) { return describe_json(value); }

// Scene files larger than this are refused before they are read (the largest scene here is 2 kB).
constexpr std::uintmax_t kMaxSceneBytes = 16u << 20;

// A requirement on a number: a predicate and the words that say it ("> 0").
struct Range {
  std::function<bool(double)> holds;
  std::string words;
};
const Range kAny{[](double) { return true; }, ""};
const Range kPositive{[](double x) { return x > 0.0; }, " > 0"};
const Range kNonNegative{[](double x) { return x >= 0.0; }, " >= 0"};
const Range kUnitInterval{[](double x) { return x >= 0.0 && x <= 1.0; }, " in [0, 1]"};
// Positions, velocities and accelerations far beyond any scene and far below where their products (x·x in
// volumes, v·dt, k·x) overflow a double: |value| <= 1e6 (m, m/s, m/s²).
const Range kWorldMagnitude{[](double x) { return std::abs(x) <= 1e6; }, " within +-1e6"};
// A body's uniform scale: 1e-6 to 1e6 (a mesh in millimetres takes 1e-3; smaller or larger overflow the
// stability estimate's products or need steps no run can take).
const Range kScaleRange{[](double x) { return x >= 1e-6 && x <= 1e6; }, " in [1e-6, 1e6]"};

// One JSON object being read: knows its key path, marks the keys it reads, rejects the others.
class ObjectReader {
 public:
  ObjectReader(const json& node, std::string path, const fs::path& file)
      : node_(node), path_(std::move(path)), file_(file) {
    if (!node_.is_object()) fail(path_, "expected an object", &node_);
  }

  [[noreturn]] void fail(const std::string& path, const std::string& expected, const json* got) const {
    std::string message = file_.string() + ": " + (path.empty() ? "(top level)" : path) + ": " + expected;
    if (got != nullptr) message += ", got " + describe(*got);
    throw softbody::InputError(message);
  }

  std::string child(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  bool has(const std::string& key) {
    known_.insert(key);
    return node_.contains(key);
  }
  const json& at(const std::string& key) { return node_.at(key); }

  double number(const std::string& key, double fallback, const Range& range = kAny) {
    if (!has(key)) return fallback;
    return checked_number(at(key), child(key), range);
  }

  double checked_number(const json& value, const std::string& path, const Range& range) const {
    if (!value.is_number()) fail(path, "expected a number" + range.words, &value);
    const double x = value.get<double>();
    if (!std::isfinite(x) || !range.holds(x)) fail(path, "expected a finite number" + range.words, &value);
    return x;
  }

  int integer(const std::string& key, int fallback, int lo, int hi) {
    if (!has(key)) return fallback;
    const json& value = at(key);
    const std::string words = "an integer in " + std::to_string(lo) + ".." + std::to_string(hi);
    if (!value.is_number_integer()) fail(child(key), "expected " + words, &value);
    const auto x = value.get<long long>();
    if (x < lo || x > hi) fail(child(key), "expected " + words, &value);
    return static_cast<int>(x);
  }

  bool boolean(const std::string& key, bool fallback) {
    if (!has(key)) return fallback;
    if (!at(key).is_boolean()) fail(child(key), "expected true or false", &at(key));
    return at(key).get<bool>();
  }

  std::string string(const std::string& key, const std::string& fallback) {
    if (!has(key)) return fallback;
    if (!at(key).is_string() || at(key).get<std::string>().empty()) {
      fail(child(key), "expected a non-empty string", &at(key));
    }
    return at(key).get<std::string>();
  }

  template <typename Enum>
  Enum choice(const std::string& key, Enum fallback, const std::vector<std::pair<std::string, Enum>>& options) {
    if (!has(key)) return fallback;
    std::string words = "expected one of";
    for (const auto& [name, value] : options) {
      if (at(key).is_string() && at(key).get<std::string>() == name) return value;
      words += " \"" + name + "\"";
    }
    fail(child(key), words, &at(key));
  }

  Vec3 vec3(const std::string& key, const Vec3& fallback, const Range& range = kWorldMagnitude) {
    if (!has(key)) return fallback;
    const json& value = at(key);
    if (!value.is_array() || value.size() != 3) fail(child(key), "expected an array of 3 numbers", &value);
    Vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = checked_number(value[i], child(key) + "." + std::to_string(i), range);
    return v;
  }

  std::array<float, 3> color(const std::string& key, const std::array<float, 3>& fallback) {
    if (!has(key)) return fallback;
    const json& value = at(key);
    if (!value.is_array() || value.size() != 3)
      fail(child(key), "expected an RGB array of 3 numbers in [0, 1]", &value);
    std::array<float, 3> rgb{};
    for (int i = 0; i < 3; ++i) {
      rgb[i] = static_cast<float>(checked_number(value[i], child(key) + "." + std::to_string(i), kUnitInterval));
    }
    return rgb;
  }

  // Rejects keys this reader never asked for (typos), naming the first one and the keys it knows.
  void reject_unknown() const {
    for (const auto& [key, value] : node_.items()) {
      if (known_.count(key) == 0) {
        std::string words = "unknown key (known keys:";
        for (const std::string& k : known_) words += " " + k;
        fail(child(key), words + ")", nullptr);
      }
    }
  }

  const fs::path& file() const { return file_; }

 private:
  const json& node_;
  std::string path_;
  const fs::path& file_;
  std::set<std::string> known_;
};

sim::Solver read_solver(ObjectReader& top) {
  sim::Solver solver;
  if (!top.has("solver")) return solver;
  ObjectReader r(top.at("solver"), "solver", top.file());
  std::vector<std::pair<std::string, sim::IntegratorKind>> integrators;
  for (const sim::IntegratorInfo& integrator : sim::kIntegrators) {
    integrators.emplace_back(integrator.name, integrator.kind);
  }
  solver.integrator = r.choice<sim::IntegratorKind>("integrator", solver.integrator, integrators);
  if (r.has("dt") && r.at("dt").is_string()) {
    if (r.at("dt").get<std::string>() != "auto")
      r.fail(r.child("dt"), "expected a number > 0 or \"auto\"", &r.at("dt"));
    solver.dt_auto = true;
  } else {
    solver.dt_s = r.number("dt", solver.dt_s, kPositive);
  }
  // xpbd's substeps per frame interval: a whole number >= 1 or "auto" (sim::Solver::substeps).
  if (r.has("substeps") && r.at("substeps").is_string()) {
    if (r.at("substeps").get<std::string>() != "auto") {
      r.fail(r.child("substeps"), "expected a whole number >= 1 or \"auto\"", &r.at("substeps"));
    }
    solver.substeps_auto = true;
  } else {
    solver.substeps = r.integer("substeps", solver.substeps, 1, 1000000);
  }
  solver.retry = r.boolean("retry", solver.retry);
  solver.tolerance = r.number("tolerance", solver.tolerance, kPositive);
  solver.threads = r.integer("threads", solver.threads, 0, 256);
  r.reject_unknown();
  return solver;
}

// The smooth contact's keys, read whatever the contact model, so that --set can switch a scene to smooth.
void read_smooth_contact(ObjectReader& r, sim::SmoothContact& smooth) {
  smooth.time_constant_s = r.number("time_constant", smooth.time_constant_s, kPositive);
  if (r.has("damping_ratio")) smooth.damping_ratio = r.number("damping_ratio", 0.0, kNonNegative);
  smooth.slip_speed_m_per_s = r.number("slip_speed", smooth.slip_speed_m_per_s, kPositive);
  smooth.smoothing_m = r.number("smoothing", smooth.smoothing_m, kPositive);
}

std::optional<sim::Floor> read_floor(ObjectReader& top) {
  if (!top.has("floor") || top.at("floor").is_null()) return std::nullopt;
  ObjectReader r(top.at("floor"), "floor", top.file());
  sim::Floor floor;
  floor.height_m = r.number("height", floor.height_m, kWorldMagnitude);
  floor.contact = r.choice<sim::FloorContact>("contact", floor.contact,
                                              {{"paper", sim::FloorContact::Paper},
                                               {"friction", sim::FloorContact::Friction},
                                               {"smooth", sim::FloorContact::Smooth}});
  floor.material.restitution = r.number("restitution", floor.material.restitution, kUnitInterval);
  floor.material.friction = r.number("friction", floor.material.friction, kNonNegative);
  read_smooth_contact(r, floor.smooth);
  r.reject_unknown();
  return floor;
}

std::string read_mesh_spec(ObjectReader& r, Body& body) {
  const std::string spec = r.string("mesh", body.mesh);
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

// "stiffness": N/m, or {"youngs": Pa, "thickness": m} or {"frequency": Hz}.
void read_stiffness(ObjectReader& body_reader, Body& body) {
  if (!body_reader.has("stiffness") || !body_reader.at("stiffness").is_object()) {
    body.stiffness_N_per_m = body_reader.number("stiffness", body.stiffness_N_per_m, kNonNegative);
    return;
  }
  ObjectReader r(body_reader.at("stiffness"), body_reader.child("stiffness"), body_reader.file());
  sim::StiffnessIntent intent;
  intent.youngs_Pa = r.number("youngs", 0.0, kPositive);
  intent.thickness_m = r.number("thickness", intent.thickness_m, kPositive);
  intent.frequency_Hz = r.number("frequency", 0.0, kPositive);
  if ((intent.youngs_Pa > 0.0) == (intent.frequency_Hz > 0.0)) {
    r.fail(body_reader.child("stiffness"),
           "expected exactly one of \"youngs\" (Pa, with \"thickness\" in m) or \"frequency\" (Hz)", nullptr);
  }
  r.reject_unknown();
  body.intent.stiffness = intent;
}

// "damping": N·s/m, or {"ratio": ζ} (fraction of critical damping of the breathing mode).
void read_damping(ObjectReader& body_reader, Body& body) {
  if (!body_reader.has("damping") || !body_reader.at("damping").is_object()) {
    body.damping_N_s_per_m = body_reader.number("damping", body.damping_N_s_per_m, kNonNegative);
    return;
  }
  ObjectReader r(body_reader.at("damping"), body_reader.child("damping"), body_reader.file());
  if (!r.has("ratio")) r.fail(r.child("ratio"), "expected a damping ratio >= 0 (1: critical)", nullptr);
  body.intent.damping_ratio = r.number("ratio", 0.0, kNonNegative);
  r.reject_unknown();
}

// "pressure": nRT in J, or {"inflation": f, "start": "equilibrium" | "rest"}.
void read_pressure(ObjectReader& body_reader, Body& body) {
  if (!body_reader.has("pressure") || !body_reader.at("pressure").is_object()) {
    body.pressure_J = body_reader.number("pressure", body.pressure_J, kNonNegative);
    return;
  }
  ObjectReader r(body_reader.at("pressure"), body_reader.child("pressure"), body_reader.file());
  sim::PressureIntent intent;
  intent.inflation =
      r.number("inflation", intent.inflation, Range{[](double x) { return x >= 0.0 && x < 1.0; }, " in [0, 1)"});
  intent.start_at_equilibrium = r.choice<bool>("start", true, {{"equilibrium", true}, {"rest", false}});
  r.reject_unknown();
  body.intent.pressure = intent;
}

// "repair": true | false, or {"degenerate", "holes": booleans (default true), "parts": "union" (default) | "keep" |
// "largest"}.
void read_repair(ObjectReader& body_reader, Body& body) {
  if (!body_reader.has("repair")) return;
  const json& value = body_reader.at("repair");
  if (value.is_boolean()) {
    if (value.get<bool>()) body.repair = mesh::full_repair();
    return;
  }
  if (!value.is_object()) {
    body_reader.fail(body_reader.child("repair"), "expected true, false or an object of repair steps", &value);
  }
  ObjectReader r(value, body_reader.child("repair"), body_reader.file());
  mesh::RepairOptions repair = mesh::full_repair();
  repair.degenerate = r.boolean("degenerate", repair.degenerate);
  repair.holes = r.boolean("holes", repair.holes);
  repair.parts = r.choice<mesh::PartsPolicy>("parts", repair.parts,
                                             {{"union", mesh::PartsPolicy::Union},
                                              {"keep", mesh::PartsPolicy::Keep},
                                              {"largest", mesh::PartsPolicy::Largest}});
  r.reject_unknown();
  body.repair = repair;
}

// "resolution": N (the proxy's vertex count) or {"edge_length": L} (its edge length, metres once placed);
// null as if left out.
void read_resolution(ObjectReader& r, Body& body) {
  if (!r.has("resolution") || r.at("resolution").is_null()) return;  // null: simulate the mesh as it is
  const json& value = r.at("resolution");
  if (value.is_object()) {
    ObjectReader inner(value, r.child("resolution"), r.file());
    if (!inner.has("edge_length")) {
      inner.fail(r.child("resolution"), "expected {\"edge_length\": L} with L > 0 in metres", &value);
    }
    body.resolution_edge_length_m = inner.number("edge_length", 0.0, kPositive);
    inner.reject_unknown();
    return;
  }
  body.resolution_vertices = r.integer("resolution", 0, 20, 1000000);
}

// "bending": k_b in N/m, or {"ratio": r} (k_b = r k, relative to the edge springs).
void read_bending(ObjectReader& body_reader, Body& body) {
  if (!body_reader.has("bending") || !body_reader.at("bending").is_object()) {
    body.bending_N_per_m = body_reader.number("bending", body.bending_N_per_m, kNonNegative);
    return;
  }
  ObjectReader r(body_reader.at("bending"), body_reader.child("bending"), body_reader.file());
  if (!r.has("ratio"))
    r.fail(r.child("ratio"), "expected a ratio >= 0 of the bending links' stiffness to the edges'", nullptr);
  body.intent.bending_ratio = r.number("ratio", 0.0, kNonNegative);
  r.reject_unknown();
}

Body read_body(const json& node, const std::string& path, const fs::path& file) {
  ObjectReader r(node, path, file);
  Body body;
  body.mesh = read_mesh_spec(r, body);
  body.position_m = r.vec3("position", body.position_m);
  body.scale = r.number("scale", body.scale, kScaleRange);
  body.velocity_m_per_s = r.vec3("velocity", body.velocity_m_per_s);
  body.mass_kg = r.number("mass", body.mass_kg, kPositive);
  read_stiffness(r, body);
  read_damping(r, body);
  read_pressure(r, body);
  read_bending(r, body);
  body.split = r.boolean("split", body.split);
  read_repair(r, body);
  read_resolution(r, body);
  body.color = r.color("color", body.color);
  body.pattern = r.choice<Pattern>(
      "pattern", body.pattern, {{"none", Pattern::None}, {"checker", Pattern::Checker}, {"stripes", Pattern::Stripes}});
  r.reject_unknown();
  return body;
}

std::vector<Body> read_bodies(ObjectReader& top) {
  if (!top.has("bodies")) top.fail("bodies", "expected an array of at least one body", nullptr);
  const json& list = top.at("bodies");
  if (!list.is_array() || list.empty()) top.fail("bodies", "expected an array of at least one body", &list);
  std::vector<Body> bodies;
  for (std::size_t i = 0; i < list.size(); ++i) {
    bodies.push_back(read_body(list[i], "bodies." + std::to_string(i), top.file()));
  }
  return bodies;
}

sim::BodyContact read_collisions(ObjectReader& top) {
  sim::BodyContact collisions;
  if (!top.has("collisions")) return collisions;
  ObjectReader r(top.at("collisions"), "collisions", top.file());
  collisions.contact = r.choice<sim::BodyContactModel>(
      "contact", collisions.contact,
      {{"impulse", sim::BodyContactModel::Impulse}, {"smooth", sim::BodyContactModel::Smooth}});
  collisions.material.restitution = r.number("restitution", collisions.material.restitution, kUnitInterval);
  collisions.material.friction = r.number("friction", collisions.material.friction, kNonNegative);
  collisions.push_speed_m_per_s = r.number("push_speed", collisions.push_speed_m_per_s, kPositive);
  read_smooth_contact(r, collisions.smooth);
  r.reject_unknown();
  return collisions;
}

int even_size(ObjectReader& r, const std::string& key, int fallback) {
  const int size = r.integer(key, fallback, 2, 8192);
  if (size % 2 != 0) r.fail(r.child(key), "expected an even number of pixels (video encoders need it)", &r.at(key));
  return size;
}

// 1 to 64 frame numbers (>= 0, each once), sorted: the contact sheet's tiles in reading order.
std::vector<int> frame_list(ObjectReader& r, const std::string& key) {
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

RenderSettings read_render(ObjectReader& top) {
  RenderSettings render;
  if (!top.has("render")) return render;
  ObjectReader r(top.at("render"), "render", top.file());
  render.width_px = even_size(r, "width", render.width_px);
  render.height_px = even_size(r, "height", render.height_px);
  render.msaa = r.integer("msaa", render.msaa, 1, 4);
  if (render.msaa == 3) r.fail("render.msaa", "expected 1, 2 or 4 samples", &r.at("msaa"));
  render.shadows = r.boolean("shadows", render.shadows);
  render.background = r.color("background", render.background);
  if (r.has("figure_frames") && r.at("figure_frames").is_array()) {
    render.figure_frame_list = frame_list(r, "figure_frames");
    render.figure_frames = static_cast<int>(render.figure_frame_list.size());
  } else {
    render.figure_frames = r.integer("figure_frames", render.figure_frames, 0, 64);
  }
  render.backend = r.choice<GlBackend>(
      "backend", render.backend, {{"auto", GlBackend::Auto}, {"egl", GlBackend::Egl}, {"osmesa", GlBackend::OsMesa}});
  r.reject_unknown();
  return render;
}

Camera read_camera(ObjectReader& top) {
  Camera camera;
  if (!top.has("camera")) return camera;
  ObjectReader r(top.at("camera"), "camera", top.file());
  camera.given = true;
  camera.position_m = r.vec3("position", camera.position_m);
  camera.target_m = r.vec3("target", camera.target_m);
  camera.up = r.vec3("up", camera.up);
  camera.fov_deg =
      r.number("fov", camera.fov_deg, Range{[](double x) { return x > 0 && x < 180; }, " in (0, 180) degrees"});
  if ((camera.target_m - camera.position_m).norm() == 0.0)
    r.fail("camera.target", "expected a point other than camera.position", nullptr);
  if (camera.up.norm() == 0.0 || camera.up.cross(camera.target_m - camera.position_m).norm() == 0.0) {
    r.fail("camera.up", "expected a non-zero vector not parallel to the view direction", nullptr);
  }
  r.reject_unknown();
  return camera;
}

Light read_light(ObjectReader& top) {
  Light light;
  if (!top.has("light")) return light;
  ObjectReader r(top.at("light"), "light", top.file());
  light.direction = r.vec3("direction", light.direction);
  if (light.direction.norm() == 0.0) r.fail("light.direction", "expected a non-zero vector", nullptr);
  light.color = r.color("color", light.color);
  light.ambient = static_cast<float>(r.number("ambient", light.ambient, kUnitInterval));
  r.reject_unknown();
  return light;
}

// "limits": what a mesh file may hold, raised for large meshes (mesh/mesh_limits.hpp).
mesh::MeshLimits read_limits(ObjectReader& top) {
  mesh::MeshLimits limits;
  if (!top.has("limits")) return limits;
  ObjectReader r(top.at("limits"), "limits", top.file());
  constexpr int kMost = 2'000'000'000;
  limits.max_triangles = r.integer("max_triangles", static_cast<int>(limits.max_triangles), 1, kMost);
  limits.max_vertices = r.integer("max_vertices", static_cast<int>(limits.max_vertices), 1, kMost);
  const int megabytes = r.integer("max_file_mb", static_cast<int>(limits.max_file_bytes >> 20), 1, 1 << 20);
  limits.max_file_bytes = static_cast<std::uintmax_t>(megabytes) << 20;
  r.reject_unknown();
  return limits;
}

Output read_output(ObjectReader& top, const std::string& name) {
  Output output;
  output.dir = fs::path("out") / name;
  if (!top.has("output")) return output;
  ObjectReader r(top.at("output"), "output", top.file());
  output.dir = r.string("dir", output.dir.string());
  output.pattern = r.string("pattern", output.pattern);
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
  ObjectReader top(document, "", file);
  Scene s;
  s.source = file;
  s.name = top.string("name", fs::path(file).stem().string());
  if (s.name.find_first_of("/\\") != std::string::npos || s.name == "." || s.name == "..") {
    top.fail("name", "expected a name without slashes, other than \".\" and \"..\" (it names the folder out/NAME)",
             &top.at("name"));
  }
  s.duration_s = top.number("duration", s.duration_s, kPositive);
  s.fps = top.integer("fps", s.fps, 1, 1000);
  s.solver = read_solver(top);
  s.gravity_m_per_s2 = top.vec3("gravity", s.gravity_m_per_s2);
  s.floor = read_floor(top);
  s.limits = read_limits(top);
  s.bodies = read_bodies(top);
  s.collisions = read_collisions(top);
  s.render = read_render(top);
  s.camera = read_camera(top);
  s.light = read_light(top);
  s.output = read_output(top, s.name);
  json simulation = document;
  for (const char* key : {"name", "render", "camera", "light", "output", "limits"}) simulation.erase(key);
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
