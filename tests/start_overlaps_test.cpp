// The notes before a run for bodies that start inside each other or inside a collider (setup/start_overlaps.hpp):
// what they measure on overlaps of known size, that touching bodies give none, and their bound on a scene of many.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "setup/start_overlaps.hpp"
#include "test_helpers.hpp"

namespace {

// Balls of radius 1 m (`mesh`) at these centres on the x axis, or of these scales.
sim::World balls(const std::vector<double>& centres_x, const std::vector<double>& scales = {},
                 const std::string& mesh = "icosphere:2") {
  std::string bodies;
  for (std::size_t b = 0; b < centres_x.size(); ++b) {
    bodies += (b ? ", " : "") + std::string(R"({ "mesh": ")") + mesh + R"(", "position": [)" +
              std::to_string(centres_x[b]) + R"(, 0, 0], "scale": )" +
              std::to_string(scales.empty() ? 1.0 : scales[b]) + " }";
  }
  return testing_support::world_from_text(R"({ "gravity": [0, 0, 0], "bodies": [ )" + bodies + " ] }");
}

std::vector<std::string> overlap_notes(const sim::World& world, double budget = setup::kOverlapBudget) {
  std::vector<std::string> names, notes;
  for (std::size_t b = 0; b < world.model.bodies.size(); ++b) names.push_back("bodies." + std::to_string(b));
  setup::note_overlapping_bodies(world.model, world.state, names, notes, budget);
  return notes;
}

TEST(StartOverlaps, BallsTouchingOrApartGiveNoNote) {
  EXPECT_TRUE(overlap_notes(balls({-1.0, 1.0})).empty()) << "touching at one point";
  EXPECT_TRUE(overlap_notes(balls({-3.0, 3.0})).empty()) << "apart";
}

// Two balls 10 cm into each other (the case collisions.push_speed was tuned on, tests/collision_test.cpp): a few
// vertices of each inside the other, the same share both ways.
TEST(StartOverlaps, TwoBallsAFewCentimetresIntoEachOther) {
  const std::vector<std::string> notes = overlap_notes(balls({-0.95, 0.95}));
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("bodies.0 and bodies.1 start inside each other (about "), std::string::npos) << notes[0];
}

// A ball of radius 0.3 m at the centre of one of 1 m: all of it inside the other, none of the other inside it.
TEST(StartOverlaps, ABallInsideAnotherIsAllInsideIt) {
  const std::vector<std::string> notes = overlap_notes(balls({0.0, 0.0}, {0.3, 1.0}));
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("(about 1e+02 % of the first's vertices inside the second, 0 % of the second's inside the "
                          "first)"),
            std::string::npos)
      << notes[0];
}

// 40 balls at nearly one place: 780 overlapping pairs. The pairs named one by one stop at kOverlapNotes and the test
// at its budget (here 2e6 vertex-face evaluations, about 300 pairs' worth at icosphere:1), each said in one more note,
// so that such a scene does not spend minutes (or lines) on it.
TEST(StartOverlaps, ASceneOfManyOverlapsIsBounded) {
  std::vector<double> centres;
  for (int b = 0; b < 40; ++b) centres.push_back(0.01 * b);
  const std::vector<std::string> notes = overlap_notes(balls(centres, {}, "icosphere:1"), 2e6);
  ASSERT_EQ(notes.size(), static_cast<std::size_t>(setup::kOverlapNotes) + 2) << notes.back();
  EXPECT_NE(notes[setup::kOverlapNotes].find("more pairs of bodies start inside each other"), std::string::npos);
  EXPECT_NE(notes.back().find("the test for bodies that start inside each other stopped after "), std::string::npos)
      << notes.back();
  EXPECT_NE(notes.back().find(" of the 780 pairs whose boxes overlap"), std::string::npos) << notes.back();
}

}  // namespace
