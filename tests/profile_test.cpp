// The per-phase counters behind --profile: a scope adds its time and one call, nested scopes both count,
// other threads' counters are merged, and nothing is counted while profiling is off.
#include <atomic>
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "core/profile.hpp"

namespace {

using softbody::ProfilePhase;
using softbody::ProfileScope;

const softbody::ProfileReport::Row& row(const softbody::ProfileReport& report, ProfilePhase phase) {
  return report.phases[static_cast<std::size_t>(phase)];
}

void sleep_ms(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

TEST(Profile, AScopeAddsItsTimeAndOneCallAndAnOuterScopeHoldsTheInner) {
  softbody::start_profiling();
  {
    const ProfileScope step(ProfilePhase::step);
    {
      const ProfileScope guard(ProfilePhase::guard);
      sleep_ms(3);
    }
    sleep_ms(2);
  }
  softbody::stop_profiling();
  const softbody::ProfileReport report = softbody::profile_report();
  EXPECT_EQ(row(report, ProfilePhase::guard).calls, 1);
  EXPECT_EQ(row(report, ProfilePhase::step).calls, 1);
  // sleep_for sleeps at least as long as asked; the outer scope holds the inner one and its own 2 ms.
  EXPECT_GE(row(report, ProfilePhase::guard).seconds, 0.003);
  EXPECT_GE(row(report, ProfilePhase::step).seconds, row(report, ProfilePhase::guard).seconds + 0.002);
  EXPECT_GE(report.wall_s, row(report, ProfilePhase::step).seconds);
  EXPECT_EQ(row(report, ProfilePhase::forces).calls, 0);
}

TEST(Profile, CallsAddUpAndStartingAgainZeroesThem) {
  softbody::start_profiling();
  for (int i = 0; i < 5; ++i) const ProfileScope forces(ProfilePhase::forces);
  EXPECT_EQ(row(softbody::profile_report(), ProfilePhase::forces).calls, 5);
  softbody::start_profiling();
  EXPECT_EQ(row(softbody::profile_report(), ProfilePhase::forces).calls, 0);
  softbody::stop_profiling();
}

TEST(Profile, NothingIsCountedWhileOff) {
  softbody::start_profiling();
  softbody::stop_profiling();
  {
    const ProfileScope gas(ProfilePhase::gas);
    EXPECT_FALSE(softbody::profiling());
  }
  EXPECT_EQ(row(softbody::profile_report(), ProfilePhase::gas).calls, 0);
}

TEST(Profile, OtherThreadsCountersAreMergedWhileTheyRunAndAfterTheyEnd) {
  softbody::start_profiling();
  std::thread ended([] { const ProfileScope gas(ProfilePhase::gas); });
  ended.join();
  std::atomic<bool> counted{false}, done{false};
  std::thread running([&] {
    { const ProfileScope gas(ProfilePhase::gas); }
    counted = true;
    while (!done) std::this_thread::yield();
  });
  while (!counted) std::this_thread::yield();
  EXPECT_EQ(row(softbody::profile_report(), ProfilePhase::gas).calls, 2);
  done = true;
  running.join();
  EXPECT_EQ(row(softbody::profile_report(), ProfilePhase::gas).calls, 2);
  softbody::stop_profiling();
}

TEST(Profile, TheTableIndentsNestedPhasesAndLeavesOutThoseWithoutCalls) {
  softbody::ProfileReport report;
  report.wall_s = 2.0;
  report.phases[static_cast<std::size_t>(ProfilePhase::step)] = {1.0, 100};
  report.phases[static_cast<std::size_t>(ProfilePhase::integrate)] = {0.8, 100};
  report.phases[static_cast<std::size_t>(ProfilePhase::forces)] = {0.5, 200};
  const std::string table = softbody::format_profile(report);
  EXPECT_NE(table.find("2.000 s of wall time"), std::string::npos) << table;
  EXPECT_NE(table.find("\nstep "), std::string::npos) << table;
  EXPECT_NE(table.find("\n  integrate "), std::string::npos) << table;
  // 0.5 s in 200 calls: 2500 µs each, 25 % of the wall time.
  EXPECT_NE(table.find("\n    forces                 0.5000   25.0 %        200      2500.00\n"), std::string::npos)
      << table;
  EXPECT_EQ(table.find("\nrender "), std::string::npos) << table;
}

}  // namespace
