// The profile's counters: one block per thread, registered on the thread's first scope, summed on reading.
#include "core/profile.hpp"

#include <algorithm>
#include <cstdio>
#include <mutex>
#include <vector>

namespace softbody {
namespace {

struct PhaseInfo {
  const char* name;
  ProfilePhase parent;
};

using P = ProfilePhase;
constexpr std::array<PhaseInfo, kProfilePhaseCount> kPhases = {{
    {"setup", P::setup},
    {"step", P::step},
    {"integrate", P::step},
    {"forces", P::integrate},
    {"gas", P::integrate},
    {"smooth contact", P::integrate},
    {"constraint sweeps", P::integrate},
    {"body contact", P::step},
    {"floor contact", P::step},
    {"guard", P::step},
    {"frame guard", P::frame_guard},
    {"csv write", P::csv_write},
    {"mesh write", P::mesh_write},
    {"snapshot", P::snapshot},
    {"render", P::render},
    {"read-back", P::read_back},
    {"png encode", P::png_encode},
    {"png store", P::png_store},
    {"video pipe", P::video_pipe},
}};

constexpr std::size_t index_of(ProfilePhase phase) { return static_cast<std::size_t>(phase); }

// One thread's counters. Only that thread writes them (load + store, no read-modify-write); readers sum them.
struct Counters {
  std::array<std::atomic<std::int64_t>, kProfilePhaseCount> ns{};
  std::array<std::atomic<std::int64_t>, kProfilePhaseCount> calls{};
};

struct Registry {
  std::mutex mutex;
  std::vector<Counters*> live;                                 // the threads running now
  std::array<std::int64_t, kProfilePhaseCount> ended_ns{};     // the sums of threads that have ended
  std::array<std::int64_t, kProfilePhaseCount> ended_calls{};  //
  std::int64_t start_ns = 0;
  std::int64_t stop_ns = -1;  // -1: running
};

// Never destroyed: threads that end after main() still hand their counters in.
Registry& registry() {
  static Registry* const instance = new Registry;
  return *instance;
}

// A thread's counters, registered while the thread lives; its sums go to the registry when it ends.
class ThreadCounters {
 public:
  ThreadCounters() {
    Registry& all = registry();
    const std::lock_guard lock(all.mutex);
    all.live.push_back(&counters_);
  }
  ~ThreadCounters() {
    Registry& all = registry();
    const std::lock_guard lock(all.mutex);
    for (std::size_t p = 0; p < kPhases.size(); ++p) {
      all.ended_ns[p] += counters_.ns[p].load(std::memory_order_relaxed);
      all.ended_calls[p] += counters_.calls[p].load(std::memory_order_relaxed);
    }
    all.live.erase(std::find(all.live.begin(), all.live.end(), &counters_));
  }
  ThreadCounters(const ThreadCounters&) = delete;
  ThreadCounters& operator=(const ThreadCounters&) = delete;
  Counters& counters() { return counters_; }

 private:
  Counters counters_;
};

Counters& this_thread_counters() {
  thread_local ThreadCounters counters;
  return counters.counters();
}

void add_relaxed(std::atomic<std::int64_t>& counter, std::int64_t amount) {
  counter.store(counter.load(std::memory_order_relaxed) + amount, std::memory_order_relaxed);
}

}  // namespace

const char* profile_phase_name(ProfilePhase phase) { return kPhases[index_of(phase)].name; }
ProfilePhase profile_phase_parent(ProfilePhase phase) { return kPhases[index_of(phase)].parent; }

namespace profile_detail {

std::int64_t now_ns() {
  using namespace std::chrono;
  return duration_cast<nanoseconds>(steady_clock::now().time_since_epoch()).count();
}

void add(ProfilePhase phase, std::int64_t ns) {
  Counters& counters = this_thread_counters();
  add_relaxed(counters.ns[index_of(phase)], ns);
  add_relaxed(counters.calls[index_of(phase)], 1);
}

}  // namespace profile_detail

void start_profiling() {
  Registry& all = registry();
  {
    const std::lock_guard lock(all.mutex);
    for (Counters* counters : all.live) {
      for (auto& ns : counters->ns) ns.store(0, std::memory_order_relaxed);
      for (auto& calls : counters->calls) calls.store(0, std::memory_order_relaxed);
    }
    all.ended_ns.fill(0);
    all.ended_calls.fill(0);
    all.start_ns = profile_detail::now_ns();
    all.stop_ns = -1;
  }
  profile_detail::on.store(true, std::memory_order_relaxed);
}

void stop_profiling() {
  profile_detail::on.store(false, std::memory_order_relaxed);
  Registry& all = registry();
  const std::lock_guard lock(all.mutex);
  if (all.stop_ns < 0) all.stop_ns = profile_detail::now_ns();
}

ProfileReport profile_report() {
  Registry& all = registry();
  const std::lock_guard lock(all.mutex);
  std::array<std::int64_t, kProfilePhaseCount> ns = all.ended_ns, calls = all.ended_calls;
  for (const Counters* counters : all.live) {
    for (std::size_t p = 0; p < kPhases.size(); ++p) {
      ns[p] += counters->ns[p].load(std::memory_order_relaxed);
      calls[p] += counters->calls[p].load(std::memory_order_relaxed);
    }
  }
  ProfileReport report;
  for (std::size_t p = 0; p < kPhases.size(); ++p) {
    report.phases[p].seconds = static_cast<double>(ns[p]) * 1e-9;
    report.phases[p].calls = calls[p];
  }
  const std::int64_t end_ns = all.stop_ns >= 0 ? all.stop_ns : profile_detail::now_ns();
  report.wall_s = static_cast<double>(end_ns - all.start_ns) * 1e-9;
  return report;
}

namespace {

// How deep a phase sits: 0 for a phase of its own, 1 inside one, ...
int depth_of(ProfilePhase phase) {
  int depth = 0;
  for (ProfilePhase p = phase; profile_phase_parent(p) != p; p = profile_phase_parent(p)) ++depth;
  return depth;
}

}  // namespace

std::string format_profile(const ProfileReport& report) {
  std::string text;
  char line[160];
  std::snprintf(line, sizeof line, "profile: %.3f s of wall time; an indented phase is part of the one above it\n",
                report.wall_s);
  text += line;
  std::snprintf(line, sizeof line, "%-22s %10s %8s %10s %13s\n", "phase", "total s", "share", "calls", "mean µs");
  text += line;
  for (std::size_t p = 0; p < kPhases.size(); ++p) {
    const ProfileReport::Row& row = report.phases[p];
    if (row.calls == 0) continue;
    const auto phase = static_cast<ProfilePhase>(p);
    const std::string name = std::string(static_cast<std::size_t>(2 * depth_of(phase)), ' ') + kPhases[p].name;
    const double share = report.wall_s > 0.0 ? 100.0 * row.seconds / report.wall_s : 0.0;
    const double mean_us = 1e6 * row.seconds / static_cast<double>(row.calls);
    std::snprintf(line, sizeof line, "%-22s %10.4f %6.1f %% %10lld %12.2f\n", name.c_str(), row.seconds, share,
                  row.calls, mean_us);
    text += line;
  }
  text +=
      "(the PNG and video writers, the second force thread and render's stepping run beside the caller's thread:\n"
      " shares can add up to more than 100 %)\n";
  return text;
}

}  // namespace softbody
