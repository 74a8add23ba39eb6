// The table of scene keys against the parser and the structs: the defaults the parser fills in are the
// structs' defaults, and the schema generated from the table says what the parser accepts.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/scene_json.hpp"
#include "scene/scene_keys.hpp"
#include "scene/scene_schema.hpp"
#include "test_helpers.hpp"

namespace {

using testing_support::scene_from_text;

TEST(SceneKeys, ParserFillsInTheStructDefaults) {
  const scene::Scene s = scene_from_text(R"({ "bodies": [ { } ] })");
  const scene::Scene defaults;
  EXPECT_EQ(s.duration_s, defaults.duration_s);
  EXPECT_EQ(s.fps, defaults.fps);
  EXPECT_EQ(s.gravity_m_per_s2, defaults.gravity_m_per_s2);
  EXPECT_FALSE(s.floor.has_value());

  const scene::Body body;
  const scene::Body& parsed = s.bodies.at(0);
  EXPECT_EQ(parsed.mesh, body.mesh);
  EXPECT_EQ(parsed.position_m, body.position_m);
  EXPECT_EQ(parsed.scale, body.scale);
  EXPECT_EQ(parsed.velocity_m_per_s, body.velocity_m_per_s);
  EXPECT_EQ(parsed.mass_kg, body.mass_kg);
  EXPECT_EQ(parsed.stiffness_N_per_m, body.stiffness_N_per_m);
  EXPECT_EQ(parsed.damping_N_s_per_m, body.damping_N_s_per_m);
  EXPECT_EQ(parsed.pressure_J, body.pressure_J);
  EXPECT_EQ(parsed.bending_N_per_m, body.bending_N_per_m);
  EXPECT_EQ(parsed.split, body.split);
  EXPECT_EQ(parsed.repair.enabled, body.repair.enabled);
  EXPECT_EQ(parsed.resolution_vertices, body.resolution_vertices);
  EXPECT_EQ(parsed.color, body.color);
  EXPECT_EQ(parsed.pattern, body.pattern);
}

TEST(SceneKeys, ParserFillsInTheStructDefaultsOfEveryObject) {
  const scene::Scene s = scene_from_text(R"({ "bodies": [ { "stiffness": { "frequency": 2 },
      "pressure": { }, "repair": { } } ], "solver": { }, "floor": { }, "limits": { }, "collisions": { },
      "render": { }, "camera": { }, "light": { }, "output": { } })");
  const sim::Solver solver;
  EXPECT_EQ(s.solver.integrator, solver.integrator);
  EXPECT_EQ(s.solver.dt_s, solver.dt_s);
  EXPECT_EQ(s.solver.substeps, solver.substeps);
  EXPECT_EQ(s.solver.retry, solver.retry);
  EXPECT_EQ(s.solver.tolerance, solver.tolerance);
  EXPECT_EQ(s.solver.threads, solver.threads);
  EXPECT_EQ(s.solver.coarse_space, solver.coarse_space);
  EXPECT_EQ(s.solver.coarse_space_auto, solver.coarse_space_auto);

  const sim::Floor floor;
  ASSERT_TRUE(s.floor.has_value());
  EXPECT_EQ(s.floor->height_m, floor.height_m);
  EXPECT_EQ(s.floor->contact, floor.contact);
  EXPECT_EQ(s.floor->material.restitution, floor.material.restitution);
  EXPECT_EQ(s.floor->material.friction, floor.material.friction);
  EXPECT_EQ(s.floor->smooth.time_constant_s, floor.smooth.time_constant_s);
  EXPECT_EQ(s.floor->smooth.damping_ratio, floor.smooth.damping_ratio);
  EXPECT_EQ(s.floor->smooth.slip_speed_m_per_s, floor.smooth.slip_speed_m_per_s);
  EXPECT_EQ(s.floor->smooth.smoothing_m, floor.smooth.smoothing_m);

  const sim::BodyContact collisions;
  EXPECT_EQ(s.collisions.contact, collisions.contact);
  EXPECT_EQ(s.collisions.material.restitution, collisions.material.restitution);
  EXPECT_EQ(s.collisions.material.friction, collisions.material.friction);
  EXPECT_EQ(s.collisions.push_speed_m_per_s, collisions.push_speed_m_per_s);
  EXPECT_EQ(s.collisions.smooth.time_constant_s, collisions.smooth.time_constant_s);
  EXPECT_EQ(s.collisions.smooth.damping_ratio, collisions.smooth.damping_ratio);
  EXPECT_EQ(s.collisions.smooth.slip_speed_m_per_s, collisions.smooth.slip_speed_m_per_s);
  EXPECT_EQ(s.collisions.smooth.smoothing_m, collisions.smooth.smoothing_m);

  const mesh::MeshLimits limits;
  EXPECT_EQ(s.limits.max_triangles, limits.max_triangles);
  EXPECT_EQ(s.limits.max_vertices, limits.max_vertices);
  EXPECT_EQ(s.limits.max_file_bytes, limits.max_file_bytes);

  const scene::RenderSettings render;
  EXPECT_EQ(s.render.width_px, render.width_px);
  EXPECT_EQ(s.render.height_px, render.height_px);
  EXPECT_EQ(s.render.msaa, render.msaa);
  EXPECT_EQ(s.render.shadows, render.shadows);
  EXPECT_EQ(s.render.background, render.background);
  EXPECT_EQ(s.render.figure_frames, render.figure_frames);
  EXPECT_EQ(s.render.backend, render.backend);

  const scene::Camera camera;
  EXPECT_EQ(s.camera.position_m, camera.position_m);
  EXPECT_EQ(s.camera.target_m, camera.target_m);
  EXPECT_EQ(s.camera.up, camera.up);
  EXPECT_EQ(s.camera.fov_deg, camera.fov_deg);

  const scene::Light light;
  EXPECT_EQ(s.light.direction, light.direction);
  EXPECT_EQ(s.light.color, light.color);
  EXPECT_EQ(s.light.ambient, light.ambient);
  EXPECT_EQ(s.output.pattern, scene::Output{}.pattern);

  const scene::Body& body = s.bodies.at(0);
  ASSERT_TRUE(body.intent.stiffness.has_value());
  EXPECT_EQ(body.intent.stiffness->thickness_m, sim::StiffnessIntent{}.thickness_m);
  ASSERT_TRUE(body.intent.pressure.has_value());
  EXPECT_EQ(body.intent.pressure->inflation, sim::PressureIntent{}.inflation);
  EXPECT_EQ(body.intent.pressure->start_at_equilibrium, sim::PressureIntent{}.start_at_equilibrium);
  EXPECT_EQ(body.repair.degenerate, mesh::full_repair().degenerate);
  EXPECT_EQ(body.repair.holes, mesh::full_repair().holes);
  EXPECT_EQ(body.repair.parts, mesh::full_repair().parts);
}

TEST(SceneKeys, SchemaKeyAcceptedAndLeftOutOfTheSimulation) {
  const scene::Scene plain = scene_from_text(R"({ "bodies": [ { } ] })");
  const scene::Scene named = scene_from_text(R"({ "$schema": "scene.schema.json", "bodies": [ { } ] })");
  EXPECT_EQ(named.simulation_json, plain.simulation_json);
}

TEST(SceneKeys, SchemaIsGeneratedFromTheTable) {
  const nlohmann::ordered_json schema = scene::scene_schema();
  EXPECT_EQ(schema["$schema"], "https://json-schema.org/draft/2020-12/schema");
  EXPECT_EQ(schema["additionalProperties"], false);
  EXPECT_EQ(schema["required"], nlohmann::ordered_json::array({"bodies"}));
  ASSERT_TRUE(schema["properties"].contains("$schema"));
  for (const scene::Key& key : scene::scene_keys().keys) EXPECT_TRUE(schema["properties"].contains(key.name));
  const auto& body = schema["properties"]["bodies"]["items"];
  EXPECT_EQ(body["additionalProperties"], false);
  EXPECT_EQ(body["properties"]["mass"]["exclusiveMinimum"], 0.0);
  EXPECT_EQ(body["properties"]["mass"]["default"], 1.0);
  EXPECT_EQ(body["properties"]["position"]["minItems"], 3);
  EXPECT_EQ(body["properties"]["position"]["maxItems"], 3);
  EXPECT_EQ(schema["properties"]["solver"]["properties"]["integrator"]["enum"].size(), sim::kIntegrators.size());
}

TEST(SceneKeys, RangeWordsAreTheMessagesWords) {
  const scene::ObjectKeys& top = scene::scene_keys();
  const scene::ObjectKeys& body = *top.key("bodies").forms.at(0).object;
  EXPECT_EQ(scene::range_words(body.key("mass").forms.at(0)), " > 0");
  EXPECT_EQ(scene::range_words(body.key("pressure").forms.at(0)), " >= 0");
  EXPECT_EQ(scene::range_words(body.key("scale").forms.at(0)), " in [1e-6, 1e6]");
  EXPECT_EQ(scene::range_words(body.key("position").forms.at(0)), " within +-1e6");
  EXPECT_EQ(scene::short_number(0.002), "0.002");
}

}  // namespace
