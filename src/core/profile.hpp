// Per-phase time counters (`--profile`): a scope adds its wall time and one call to its phase, so that the
// program itself says where a run's time goes, as Jolt's JPH_PROFILE and Box2D's b2Profile do.
//
// Off (the default), a scope costs one load and one predictable branch on entry and one on exit; on, two reads
// of the steady clock and two relaxed stores into counters of the calling thread (no lock, no shared cache
// line), merged when the report is read. The counters only read the clock: no physics value depends on them.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>

namespace softbody {

// The phases, in the order of the data flow; the report lists them in this order. A phase whose parent is not
// itself runs inside that parent (its time is part of the parent's).
enum class ProfilePhase : int {
  setup,              // the scene read, meshes loaded and prepared, the world built
  step,               // one step of the solver (retries and rejected adaptive attempts included)
  integrate,          // the integrator's update of x and v, forces evaluated inside
  forces,             // gravity, springs, dampers and bending links
  gas,                // the gas's face pass: volume and area sums
  smooth_contact,     // the smooth floor's and the smooth body contact's forces
  constraint_sweeps,  // xpbd's constraint passes
  body_contact,       // impulses between bodies after a step
  floor_contact,      // the floor's contact model after a step
  guard,              // the step's divergence checks
  frame_guard,        // the full check before a frame is handed out
  csv_write,          // CSV rows made and written
  mesh_write,         // OBJ / PLY frames and point caches
  snapshot,           // the surfaces copied for the renderer
  render,             // GL draw of a frame
  read_back,          // pixels read back from GL
  png_encode,         // PNG compression (writer thread)
  png_store,          // PNG files written (writer thread)
  video_pipe,         // frames piped to ffmpeg and its end (writer thread)
  count
};
inline constexpr int kProfilePhaseCount = static_cast<int>(ProfilePhase::count);

// The phase's name in the report ("constraint sweeps") and the phase it runs inside (itself: none).
const char* profile_phase_name(ProfilePhase phase);
ProfilePhase profile_phase_parent(ProfilePhase phase);

namespace profile_detail {
inline std::atomic<bool> on{false};
std::int64_t now_ns();
void add(ProfilePhase phase, std::int64_t ns);  // to the calling thread's counters
}  // namespace profile_detail

inline bool profiling() { return profile_detail::on.load(std::memory_order_relaxed); }

// Adds the wall time from construction to destruction, and one call, to `phase` while profiling is on.
class ProfileScope {
 public:
  explicit ProfileScope(ProfilePhase phase) : phase_(phase), start_ns_(profiling() ? profile_detail::now_ns() : -1) {}
  ~ProfileScope() {
    if (start_ns_ >= 0) profile_detail::add(phase_, profile_detail::now_ns() - start_ns_);
  }
  ProfileScope(const ProfileScope&) = delete;
  ProfileScope& operator=(const ProfileScope&) = delete;

 private:
  ProfilePhase phase_;
  std::int64_t start_ns_;  // -1: profiling was off at construction
};

// Runs work() inside a scope of `phase` and returns what it returns.
template <class Work>
decltype(auto) profiled(ProfilePhase phase, Work&& work) {
  const ProfileScope scope(phase);
  return work();
}

// Every thread's counters summed (threads that ended included), and the wall time since start_profiling()
// (until stop_profiling(), or now).
struct ProfileReport {
  struct Row {
    double seconds = 0.0;
    long long calls = 0;
  };
  std::array<Row, kProfilePhaseCount> phases{};
  double wall_s = 0.0;
};

// Zeroes every counter, starts the wall clock and turns profiling on. Call it while no scope is open on another
// thread (before a run).
void start_profiling();
// Stops the wall clock and turns profiling off (scopes open now still add their time when they close).
void stop_profiling();
ProfileReport profile_report();

// The report as a table: phase (indented under its parent), total s, share of the wall time, calls, mean µs
// per call; phases without calls left out. Threads other than the caller's (the PNG and video writers, the
// second force thread, the stepping thread of `render`) overlap it: shares can add up to more than 100 %.
std::string format_profile(const ProfileReport& report);

}  // namespace softbody
