// The table of scene keys: names, forms, units, ranges, defaults and descriptions, in the order the parser
// reads them.
#include "scene/scene_keys.hpp"

#include <cstdio>
#include <stdexcept>

#include "sim/model/settings.hpp"

namespace scene {
namespace {

using nlohmann::json;

Bound above(double x) { return {x, true}; }
Bound at_least(double x) { return {x, false}; }
Bound below(double x) { return {x, true}; }
Bound at_most(double x) { return {x, false}; }

Form number(std::optional<Bound> minimum = {}, std::optional<Bound> maximum = {}, std::string words = "") {
  Form form;
  form.minimum = minimum;
  form.maximum = maximum;
  form.range_words = std::move(words);
  return form;
}
Form positive() { return number(above(0.0)); }
Form non_negative() { return number(at_least(0.0)); }
Form unit_interval() { return number(at_least(0.0), at_most(1.0)); }
// Positions, velocities and accelerations far beyond any scene and far below where their products (x·x in
// volumes, v·dt, k·x) overflow a double: |value| <= 1e6 (m, m/s, m/s²).
Form world_magnitude() { return number(at_least(-1e6), at_most(1e6)); }

Form integer(long long lo, long long hi) {
  Form form = number(at_least(static_cast<double>(lo)), at_most(static_cast<double>(hi)));
  form.kind = FormKind::Integer;
  return form;
}
Form of_kind(FormKind kind) {
  Form form;
  form.kind = kind;
  return form;
}
Form choice(std::vector<std::string> choices) {
  Form form = of_kind(FormKind::Choice);
  form.choices = std::move(choices);
  return form;
}
Form vec3() {
  Form form = world_magnitude();
  form.kind = FormKind::Vector;
  return form;
}
Form color() {
  Form form = unit_interval();
  form.kind = FormKind::Color;
  return form;
}
Form object(const ObjectKeys& keys) {
  Form form = of_kind(FormKind::Object);
  form.object = &keys;
  return form;
}
Form object_list(const ObjectKeys& keys) {
  Form form = of_kind(FormKind::ObjectList);
  form.object = &keys;
  return form;
}

Key key(std::string name, std::vector<Form> forms, std::string unit, std::string description, json default_value) {
  Key k;
  k.name = std::move(name);
  k.forms = std::move(forms);
  k.unit = std::move(unit);
  k.description = std::move(description);
  k.default_value = std::move(default_value);
  return k;
}
Key key_without_default(std::string name, std::vector<Form> forms, std::string unit, std::string description,
                        std::string default_words = "") {
  Key k = key(std::move(name), std::move(forms), std::move(unit), std::move(description), nullptr);
  k.default_words = std::move(default_words);
  return k;
}
Key required(Key k) {
  k.required = true;
  return k;
}

// No control character (U+0000 to U+001F, U+007F), as a JSON Schema pattern (ECMA 262).
const char* const kNoControlCharacters = "^[^\\u0000-\\u001f\\u007f]+$";

// A string that becomes a file name (at most kMaxFileNameBytes) or a path (at most kMaxPathBytes).
Key names_file(Key k, std::size_t max_bytes) {
  k.names_file = true;
  k.max_bytes = max_bytes;
  if (k.pattern.empty()) k.pattern = kNoControlCharacters;
  return k;
}

std::vector<std::string> integrator_names() {
  std::vector<std::string> names;
  for (const sim::IntegratorInfo& integrator : sim::kIntegrators) names.emplace_back(integrator.name);
  return names;
}

// The smooth contact's keys (floor and collisions), read whatever the contact model, so that --set can switch a
// scene to smooth. Per vertex of mass m the contact is a spring m/τ² and a dashpot 2ζm/τ (sim/model/settings.hpp).
void add_smooth_contact(ObjectKeys& keys, double time_constant_s) {
  keys.keys.push_back(key("time_constant", {positive()}, "s",
                          "Smooth contact: τ = 1/ω of the contact's spring; an impact of one vertex lasts about π τ.",
                          time_constant_s));
  keys.keys.push_back(key_without_default("damping_ratio", {non_negative()}, "",
                                          "Smooth contact: damping ratio ζ of the contact's dashpot.",
                                          "from the restitution e, e = exp(−πζ/√(1−ζ²))"));
  keys.keys.push_back(key("slip_speed", {positive()}, "m/s",
                          "Smooth contact: ε of the regularised Coulomb friction μ N v_t / √(|v_t|² + ε²).", 0.1));
  keys.keys.push_back(key("smoothing", {positive()}, "m",
                          "Smooth contact: the spring stiffens from 0 over the first δ of penetration (a C² ramp).",
                          0.002));
}

// Every object of the scene file. Members refer to each other (Form::object), so the table lives in one place.
struct Table {
  ObjectKeys top, solver, floor, collider, collider_key, limits, body, stiffness, damping, pressure, bending, repair,
      resolution, collisions, render, camera, light, output;

  Table() {
    fill_solver();
    fill_floor();
    fill_collider_key();
    fill_collider();
    fill_limits();
    fill_body();
    fill_collisions();
    fill_render();
    fill_camera();
    fill_light();
    fill_output();
    fill_top();
  }

  void fill_top() {
    top.path = "(top level)";
    top.description = "A scene file: JSON with // and /* */ comments. Only \"bodies\" is required.";
    Key name = key_without_default("name", {of_kind(FormKind::String)}, "",
                                   "The scene's name: names the output folder out/NAME (at most 255 bytes, no "
                                   "slash or control character).",
                                   "the scene file's name without its extension");
    name.pattern = "^[^/\\\\\\u0000-\\u001f\\u007f]+$";
    name.refused = {".", ".."};
    name = names_file(name, kMaxFileNameBytes);
    top.keys = {
        key_without_default("$schema", {of_kind(FormKind::String)}, "",
                            "The JSON Schema the file follows (for editors); the program ignores it."),
        name,
        key("duration", {positive()}, "s", "Simulated time.", 3.0),
        key("fps", {integer(1, 1000)}, "1/s", "Frames (CSV rows, images) per simulated second.", 30),
        key_without_default("solver", {object(solver)}, "", "The time integrator and its step."),
        key("gravity", {vec3()}, "m/s²", "Acceleration of gravity.", json::array({0.0, -9.81, 0.0})),
        key_without_default("floor", {of_kind(FormKind::Null), object(floor)}, "",
                            "The ground plane y = height; null or left out: no floor.", "no floor"),
        key_without_default(
            "colliders", {object_list(collider)}, "",
            "Static shapes (plane, box, sphere, capsule, triangle mesh) that move bodies and are not moved by them.",
            "none"),
        key_without_default("limits", {object(limits)}, "",
                            "The most a mesh file and the whole scene may hold (raisable)."),
        required(key_without_default("bodies", {object_list(body)}, "", "The soft bodies, at least one.")),
        key_without_default("collisions", {object(collisions)}, "", "Contact between bodies, when there are several."),
        key_without_default("render", {object(render)}, "", "The pictures `softbody render` makes."),
        key_without_default("camera", {object(camera)}, "", "Where the pictures are seen from.",
                            "framed on the bodies' whole trajectory"),
        key_without_default("light", {object(light)}, "", "The one directional light."),
        key_without_default("output", {object(output)}, "", "Where outputs are written."),
    };
  }

  void fill_solver() {
    solver.path = "solver";
    solver.description = "The time integrator and its step.";
    Form dt = positive();
    Form substeps = integer(1, 1000000);
    solver.keys = {
        key("integrator", {choice(integrator_names())}, "", "The time integrator.", "euler"),
        key("dt", {dt, choice({"auto"})}, "s",
            "Requested time step; the run takes the largest that divides 1/fps (rk45: its first trial step). "
            "\"auto\": from the stable-step estimate (xpbd and vbd: their automatic substeps, unless substeps is a "
            "number).",
            1e-4),
        key_without_default(
            "substeps", {substeps, choice({"auto"})}, "",
            "xpbd and vbd: steps per frame interval, so dt = (1/fps) / substeps. \"auto\": xpbd, the "
            "fewest that keep its stated accuracy; vbd, one per frame (at most 1/30 s; where a contact acts "
            "after the step, a paper or friction floor, a keyframed collider or the impulse contact between "
            "bodies or with itself, the contact travel limit; vbd shrinks its steps itself around smooth "
            "impacts).",
            "none: dt decides"),
        key("iterations", {integer(1, 10000), choice({"converge", "auto"})}, "",
            "vbd: Gauss-Seidel sweeps over the vertices per step. \"converge\": each step sweeps until a sweep moves "
            "no vertex by more than 3e-4 of its body's mean edge (at least 2 sweeps, at most 32): more where the "
            "step converges slowly (a body far from its shape, a fine mesh through an impact), fewer in a smooth "
            "flight. \"auto\": vbd holds the gas's volume within 1 % by itself: it sweeps as \"converge\" does with "
            "the move scaled by h / (1/30 s), halves its steps where the volume's local error exceeds 0.5 % of V "
            "per second, and takes impact_phase 0.25 unless it is given; not a lightly damped breathing that its "
            "steps damp out, where a note says so (docs/physics/integrators.md).",
            4),
        key_without_default(
            "impact_phase", {number(above(0.0), at_most(4.0))}, "",
            "vbd: around an impact on a smooth contact (floor, collider or between bodies) its steps shrink to "
            "omega h <= this, omega = 1 / time_constant (down to dt / 4096). Smaller: a truer impact, above all its "
            "friction, where the sweeps converge each step (on fine meshes more steps of 4 sweeps can add error), at "
            "more steps while it lasts. \"iterations\": \"auto\" takes 0.25 where it is not given (0.5 leaves the "
            "first impact of scenes/bounce_smooth.json at icosphere:4 2.5 cm off).",
            "0.5; 0.25 with \"iterations\": \"auto\""),
        key("coarse_space", {integer(0, 512), choice({"auto"})}, "",
            "vbd: cells per body of a coarse level (smooth displacement fields and the body's linear motions; one "
            "Newton step on them before every other sweep, in place of the affine step) for meshes of thousands of "
            "vertices, where the sweeps alone converge slowly; 0: none. \"auto\": 128 for a body of at least 5000 "
            "vertices, none below.",
            "auto"),
        key("retry", {of_kind(FormKind::Boolean)}, "",
            "A step the divergence guard rejects is retried as 2, 4, ... substeps (up to 1024).", false),
        key("tolerance", {positive()}, "m",
            "rk45 only: per-step error bound, absolute and relative, on positions and velocities.", 1e-6),
        key("threads", {integer(0, 256)}, "",
            "Threads for the force passes of large bodies and for vbd's sweeps and coarse corrections; 0: one per "
            "core. "
            "Results do not depend on it.",
            0),
    };
  }

  void fill_floor() {
    floor.path = "floor";
    floor.description = "The ground plane; null or left out: no floor.";
    floor.keys = {
        key("height", {world_magnitude()}, "m", "The plane y = height.", 0.0),
        key("contact", {choice({"paper", "friction", "smooth"})}, "",
            "paper: a vertex below is reflected and put back on the floor (Matyka & Ollila); friction: restitution "
            "and Coulomb friction impulses; smooth: a penalty spring-damper force with regularised friction.",
            "paper"),
        key("restitution", {unit_interval()}, "",
            "Normal speed kept after an impact (0 inelastic .. 1 elastic); friction and smooth contacts.", 0.5),
        key("friction", {non_negative()}, "", "Coulomb coefficient μ (static = sliding); friction and smooth contacts.",
            0.5),
    };
    add_smooth_contact(floor, 0.002);
  }

  void fill_collider() {
    collider.path = "colliders[]";
    collider.description =
        "A static, keyframed (\"keys\") or, for a mesh, point-cached (\"cache\") shape. Its own keys: plane "
        "\"normal\"; box \"size\"; sphere \"radius\"; "
        "capsule \"radius\" and \"length\"; mesh \"mesh\", \"scale\", \"thickness\" and \"cache\". The contact keys "
        "left out "
        "take the floor's values (the floor's defaults without a floor).";
    collider.keys = {
        required(key_without_default("shape", {choice({"plane", "box", "sphere", "capsule", "mesh"})}, "",
                                     "plane: the half-space behind a plane through the position; box: centred on "
                                     "the position; sphere; capsule: a cylinder along its local y with round caps; "
                                     "mesh: a triangle mesh file, solid when closed, else a sheet of a thickness.")),
        key("position", {vec3()}, "m", "The shape's centre (a plane: a point on it).", json::array({0.0, 0.0, 0.0})),
        key("rotation", {vec3()}, "°",
            "Euler angles [rx, ry, rz] in degrees, applied about the world's X, then Y, then Z (Blender's XYZ).",
            json::array({0.0, 0.0, 0.0})),
        key("normal", {vec3()}, "", "Plane: its outward normal in its own frame (then rotated), non-zero.",
            json::array({0.0, 1.0, 0.0})),
        key_without_default("size", {vec3()}, "m", "Box (required): its full edge lengths [sx, sy, sz], each > 0."),
        key_without_default("radius", {positive()}, "m", "Sphere and capsule (required): the radius."),
        key_without_default("length", {non_negative()}, "m",
                            "Capsule (required): its cylinder's length along its local y (the whole capsule is "
                            "length + 2 radius long)."),
        names_file(key_without_default("mesh", {of_kind(FormKind::String)}, "",
                                       "Mesh (required): a mesh file path relative to the scene file (any format a "
                                       "body's mesh may have, within \"limits\"), or a generator (\"icosphere:L\", "
                                       "\"cube:N\", ...). Closed: solid; open: a two-sided sheet."),
                   kMaxPathBytes),
        key("scale", {number(at_least(1e-6), at_most(1e6))}, "",
            "Mesh: uniform scale applied to the mesh before it is turned and placed at the position.", 1.0),
        key("thickness", {positive()}, "m",
            "Mesh: an open mesh's thickness: a point nearer its triangles than half of it is inside (a closed mesh "
            "does not use it).",
            0.01),
        names_file(key_without_default("cache", {of_kind(FormKind::String)}, "",
                                       "Mesh: a point cache moving the mesh's vertices, relative to the scene file: a "
                                       "PC2 file (as Blender, Maya, Houdini and softbody export --format pc2 write "
                                       "it; sample i at frame start + i × rate) or a numbered OBJ sequence such as "
                                       "\"out/collider_0_%04d.obj\" (as softbody export writes a moving collider; "
                                       "file k at frame k, each with the first's triangles). One point per vertex of "
                                       "the mesh, in its file's order (the mesh then an OBJ file or a generator). "
                                       "Frame f is at f / cache_fps seconds; positions linear in time between "
                                       "samples (the surface's velocity from them, so friction carries a body); "
                                       "before the first sample and after the last the mesh holds that pose. Not "
                                       "with \"keys\".",
                                       "none (static, or \"keys\")"),
                   kMaxPathBytes),
        key_without_default("cache_fps", {positive()}, "",
                            "With \"cache\": the frames per second its frame numbers count in.", "the scene's fps"),
        key_without_default("keys", {object_list(collider_key)}, "",
                            "A moving collider's keyframes, in increasing time: its pose at each key's time, "
                            "interpolated between them; before the first and after the last it holds its pose.",
                            "none (static)"),
        key("interpolation", {choice({"linear", "smooth"})}, "",
            "With \"keys\": linear (constant velocity between keys; rotations by slerp) or smooth (C¹: Catmull–Rom "
            "positions and scale, a C¹ rotation spline). The collider's velocity comes from the motion: friction "
            "carries a body on a moving platform.",
            "linear"),
    };
    // The floor's contact keys, each defaulting to the scene's floor value.
    for (const Key& floor_key : floor.keys) {
      if (floor_key.name == "height") continue;
      Key k = floor_key;
      k.default_value = nullptr;
      k.default_words = "the floor's";
      collider.keys.push_back(k);
    }
  }

  void fill_collider_key() {
    collider_key.path = "colliders[].keys[]";
    collider_key.description =
        "One keyframe of a moving collider: its pose at a time. Position and rotation left out take the collider's.";
    collider_key.keys = {
        required(
            key_without_default("time", {number()}, "s", "When the collider has this pose (after the key before).")),
        key_without_default("position", {vec3()}, "m", "The shape's centre (a plane: a point on it) at this time.",
                            "the collider's position"),
        key_without_default("rotation", {vec3()}, "°", "Euler angles [rx, ry, rz] at this time, as the collider's.",
                            "the collider's rotation"),
        key("scale", {positive()}, "", "Multiplies the shape's sizes (radius, size, length) at this time.", 1.0),
    };
  }

  void fill_limits() {
    limits.path = "limits";
    limits.description =
        "The most a mesh file, and the whole scene, may hold before they are read; raise them for large meshes and "
        "many bodies.";
    constexpr long long kMost = 2'000'000'000;
    limits.keys = {
        key("max_triangles", {integer(1, kMost)}, "", "Triangles (and faces a header announces) per mesh file.",
            2'000'000),
        key("max_vertices", {integer(1, kMost)}, "", "Vertices per mesh file, as written (before welding).", 2'000'000),
        key("max_file_mb", {integer(1, 1 << 20)}, "MiB", "Size of a mesh file; larger ones are not read.", 256),
        key("max_total_vertices", {integer(1, kMost)}, "",
            "Vertices of the whole scene: every body's mesh and simulation proxy and every collider's mesh, summed. "
            "Each body vertex takes about 0.4 kB of memory with the explicit integrators and 1.4 kB with vbd, 1.6 kB "
            "on several threads (4,000,000: about 6 GB).",
            4'000'000),
        key("max_total_triangles", {integer(1, kMost)}, "", "Triangles of the whole scene, summed as the vertices.",
            8'000'000),
    };
  }

  void fill_body() {
    body.path = "bodies[]";
    body.description = "One soft body: a closed triangle mesh of springs (its edges) around a gas.";
    body.keys = {
        names_file(key("mesh", {of_kind(FormKind::String)}, "",
                       "A generator (\"icosphere:L\", \"cube:N\", \"torus:M,N\", \"capsule:N\") or a mesh file path "
                       "relative to the scene file (at most 4095 bytes, no control character).",
                       "icosphere:3"),
                   kMaxPathBytes),
        key("position", {vec3()}, "m", "Where the mesh's origin is placed.", json::array({0.0, 0.0, 0.0})),
        key("rotation", {vec3()}, "°",
            "Euler angles [rx, ry, rz] in degrees turning the mesh about its origin, applied about the world's X, "
            "then Y, then Z (Blender's XYZ), after the scale and before the position.",
            json::array({0.0, 0.0, 0.0})),
        key("scale", {number(at_least(1e-6), at_most(1e6))}, "", "Uniform scale applied to the mesh before placing it.",
            1.0),
        key("velocity", {vec3()}, "m/s", "Initial velocity of every vertex.", json::array({0.0, 0.0, 0.0})),
        key("mass", {positive()}, "kg", "The whole body's mass, lumped to vertices by area.", 1.0),
        key("stiffness", {non_negative(), object(stiffness)}, "N/m",
            "Each edge spring's constant k, or an object that derives it from the mesh.", 1000.0),
        key("damping", {non_negative(), object(damping)}, "N·s/m",
            "Each spring's damper, along the spring, or {\"ratio\": ζ}.", 1.0),
        key("pressure", {non_negative(), object(pressure)}, "J",
            "nRT of the enclosed gas (0 switches the gas off), or an object that derives it from an inflation.", 50.0),
        key("bending", {non_negative(), object(bending)}, "N/m",
            "k_b of the bending links across each edge (0: none), or {\"ratio\": r}.", 0.0),
        key("split", {of_kind(FormKind::Boolean)}, "", "Each separate closed part of the mesh becomes its own body.",
            false),
        key("self_collision", {of_kind(FormKind::Boolean)}, "",
            "Its vertices also collide with its own triangles (outside each vertex's rest neighbourhood), with the "
            "collisions' contact model.",
            false),
        key("repair", {of_kind(FormKind::Boolean), object(repair)}, "",
            "Repair the mesh before it is checked: true (every step) or an object of steps.", false),
        key_without_default("resolution", {of_kind(FormKind::Null), integer(20, 1000000), object(resolution)}, "",
                            "Simulate the body on an isotropic remesh (the proxy) with about N vertices, or with "
                            "edges of about a length; the mesh follows the proxy.",
                            "none: the mesh as it is"),
        key("color", {color()}, "", "Linear RGB in [0, 1].", json::array({0.80, 0.12, 0.07})),
        key("pattern", {choice({"none", "checker", "stripes"})}, "",
            "Painted in the body's own coordinates so that its rotation shows: checker (8 × 4 cells) or stripes "
            "(8 meridians).",
            "none"),
    };
    fill_body_intents();
  }

  void fill_body_intents() {
    stiffness.path = "bodies[].stiffness";
    stiffness.description = "The springs' k from a shell material or from a frequency.";
    stiffness.exactly_one_of = {"youngs", "frequency"};
    stiffness.keys = {
        key_without_default("youngs", {positive()}, "Pa", "Young's modulus of the shell material: k = (√3/2) E t."),
        key("thickness", {positive()}, "m", "Shell thickness t (with youngs).", 1e-3),
        key_without_default("frequency", {positive()}, "Hz", "The breathing mode's frequency."),
    };
    damping.path = "bodies[].damping";
    damping.description = "The dampers' c from a damping ratio of the breathing mode.";
    damping.keys = {required(key_without_default("ratio", {non_negative()}, "", "ζ (1: critical damping)."))};
    pressure.path = "bodies[].pressure";
    pressure.description = "nRT and the springs' rest lengths from an inflation.";
    pressure.keys = {
        key("inflation", {number(at_least(0.0), below(1.0))}, "",
            "The springs are stretched by this fraction at equilibrium (0: no gas).", 0.1),
        key("start", {choice({"equilibrium", "rest"})}, "",
            "equilibrium: the mesh is the equilibrium shape (no pop); rest: the mesh is the springs' rest shape and "
            "the gas inflates it.",
            "equilibrium"),
    };
    bending.path = "bodies[].bending";
    bending.description = "The bending links' k_b relative to the edge springs: k_b = r k.";
    bending.keys = {required(key_without_default("ratio", {non_negative()}, "", "r, k_b / k."))};
    repair.path = "bodies[].repair";
    repair.description = "Single repair steps; non-manifold splitting, winding and orientation are always done.";
    repair.keys = {
        key("degenerate", {of_kind(FormKind::Boolean)}, "",
            "Remove faces with a repeated vertex, duplicate faces and zero-area faces.", true),
        key("holes", {of_kind(FormKind::Boolean)}, "", "Fill holes (triangulate, refine, fair).", true),
        key("parts", {choice({"union", "keep", "largest"})}, "",
            "Separate parts: join the overlapping ones, keep them all, or keep only the largest.", "union"),
    };
    resolution.path = "bodies[].resolution";
    resolution.description = "The proxy's edge length instead of its vertex count.";
    resolution.keys = {required(
        key_without_default("edge_length", {positive()}, "m", "The proxy's edge length, once the mesh is placed."))};
  }

  void fill_collisions() {
    collisions.path = "collisions";
    collisions.description = "Contact between bodies (vertices of one against the triangles of another).";
    collisions.keys = {
        key("contact", {choice({"impulse", "smooth"})}, "",
            "impulse: after each step a vertex inside is moved out, with restitution and friction impulses; "
            "smooth: a penalty spring-damper force with regularised friction.",
            "impulse"),
        key("restitution", {unit_interval()}, "", "Normal speed kept after an impact (0 inelastic .. 1 elastic).", 0.3),
        key("friction", {non_negative()}, "", "Coulomb coefficient μ (static = sliding).", 0.5),
        key("push_speed", {positive()}, "m/s",
            "Impulse contact: the most speed at which a vertex found inside is pushed out, beyond its approach.", 0.1),
    };
    add_smooth_contact(collisions, 0.0005);
  }

  void fill_render() {
    render.path = "render";
    render.description = "The pictures `softbody render` makes.";
    Form size = integer(2, 8192);
    size.multiple_of = 2;  // video encoders need even sizes
    Form msaa = integer(1, 4);
    msaa.excluded = {3};
    Form frame_list;
    frame_list.kind = FormKind::FrameList;
    render.keys = {
        key("width", {size}, "px", "Picture width (even: video encoders need it).", 1280),
        key("height", {size}, "px", "Picture height (even).", 720),
        key("msaa", {msaa}, "", "Samples per pixel: 1 (off), 2 or 4.", 4),
        key("shadows", {of_kind(FormKind::Boolean)}, "", "The bodies cast shadow-mapped shadows on the floor.", true),
        key("background", {color()}, "", "Linear RGB in [0, 1].", json::array({0.62, 0.72, 0.85})),
        key("figure_frames", {integer(0, 64), frame_list}, "",
            "Frames in the contact sheet figure.png, chosen from the motion (0: no figure), or a list of exactly "
            "these frame numbers.",
            8),
        key("backend", {choice({"auto", "egl", "osmesa"})}, "",
            "The OpenGL backend (the environment variable SOFTBODY_GL wins over it).", "auto"),
    };
  }

  void fill_camera() {
    camera.path = "camera";
    camera.description = "A pinhole camera; without one, render frames the bodies' whole trajectory.";
    camera.keys = {
        key("position", {vec3()}, "m", "Where the camera is.", json::array({0.0, 2.5, 9.0})),
        key("target", {vec3()}, "m", "The point it looks at (other than position).", json::array({0.0, 1.2, 0.0})),
        key("up", {vec3()}, "", "Up in the picture (not parallel to the view direction).",
            json::array({0.0, 1.0, 0.0})),
        key("fov", {number(above(0.0), below(180.0), " in (0, 180) degrees")}, "°", "Vertical field of view.", 45.0),
    };
  }

  void fill_light() {
    light.path = "light";
    light.description = "The one directional light.";
    light.keys = {
        key("direction", {vec3()}, "", "The direction the light travels (towards the scene), non-zero.",
            json::array({-0.4, -1.0, -0.35})),
        key("color", {color()}, "", "Linear RGB in [0, 1].", json::array({1.0, 1.0, 1.0})),
        key("ambient", {unit_interval()}, "", "Fraction of light that reaches every surface.", 0.25),
    };
  }

  void fill_output() {
    output.path = "output";
    output.description = "Where outputs are written.";
    output.keys = {
        names_file(key_without_default("dir", {of_kind(FormKind::String)}, "",
                                       "The output folder (at most 4095 bytes, no control character).", "out/NAME"),
                   kMaxPathBytes),
        names_file(key("pattern", {of_kind(FormKind::String)}, "",
                       "File name of the frames: ends in .png and holds one frame number conversion (%d, %04d, "
                       "...); at most 255 bytes, no control character.",
                       "frame_%04d.png"),
                   kMaxFileNameBytes),
    };
  }
};

const Table& table() {
  static const Table kTable;
  return kTable;
}

}  // namespace

const Form& Key::form(FormKind kind) const {
  for (const Form& f : forms) {
    if (f.kind == kind) return f;
  }
  throw std::logic_error("scene key table: \"" + name + "\" has no such form");
}

bool Key::accepts(FormKind kind) const {
  for (const Form& f : forms) {
    if (f.kind == kind) return true;
  }
  return false;
}

const Key& ObjectKeys::key(const std::string& name) const {
  for (const Key& k : keys) {
    if (k.name == name) return k;
  }
  throw std::logic_error("scene key table: " + path + " has no key \"" + name + "\"");
}

const ObjectKeys& scene_keys() { return table().top; }

std::vector<const ObjectKeys*> all_objects() {
  const Table& t = table();
  return {&t.top,        &t.solver,     &t.floor,   &t.collider, &t.collider_key, &t.limits,
          &t.body,       &t.stiffness,  &t.damping, &t.pressure, &t.bending,      &t.repair,
          &t.resolution, &t.collisions, &t.render,  &t.camera,   &t.light,        &t.output};
}

std::string short_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  std::string s = text;
  const std::size_t e = s.find('e');
  if (e == std::string::npos) return s;
  std::string mantissa = s.substr(0, e);
  std::string exponent = s.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent = exponent.substr(1);
  exponent.erase(0, exponent.find_first_not_of('0'));
  return mantissa + "e" + (negative ? "-" : "") + exponent;
}

std::string range_words(const Form& form) {
  if (!form.range_words.empty()) return form.range_words;
  const auto& lo = form.minimum;
  const auto& hi = form.maximum;
  if (lo && hi) {
    if (!lo->exclusive && !hi->exclusive && lo->value == -hi->value) return " within +-" + short_number(hi->value);
    return std::string(" in ") + (lo->exclusive ? "(" : "[") + short_number(lo->value) + ", " +
           short_number(hi->value) + (hi->exclusive ? ")" : "]");
  }
  if (lo) return (lo->exclusive ? " > " : " >= ") + short_number(lo->value);
  if (hi) return (hi->exclusive ? " < " : " <= ") + short_number(hi->value);
  return "";
}

}  // namespace scene
