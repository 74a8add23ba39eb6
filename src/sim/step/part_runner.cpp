// PartRunner: persistent workers woken per job through an atomic generation counter.
#include "sim/step/part_runner.hpp"

#include <chrono>

namespace sim {

namespace {

constexpr std::uint64_t kStop = ~std::uint64_t{0};
constexpr int kSpins = 200;  // polls with a pause hint before yielding
// Then polls with yields (other runnable threads on this core go first) for up to this long before
// sleeping on the futex, whose wake-up costs tens of µs on these machines: long enough to bridge the gap
// between the parts of one step and from one step to the next.
constexpr auto kYieldFor = std::chrono::microseconds(2000);

void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

// Waits until `value` differs from `old`: polls kSpins times, then sleeps until notified.
template <class T>
T wait_for_change(const std::atomic<T>& value, T old) {
  for (int spin = 0; spin < kSpins; ++spin) {
    const T now = value.load(std::memory_order_acquire);
    if (now != old) return now;
    cpu_relax();
  }
  const auto give_up = std::chrono::steady_clock::now() + kYieldFor;
  for (int poll = 1;; ++poll) {
    const T now = value.load(std::memory_order_acquire);
    if (now != old) return now;
    std::this_thread::yield();
    if (poll % 64 == 0 && std::chrono::steady_clock::now() > give_up) break;
  }
  value.wait(old, std::memory_order_acquire);
  return value.load(std::memory_order_acquire);
}

}  // namespace

PartRunner::~PartRunner() {
  if (workers_.empty()) return;
  generation_.store(kStop, std::memory_order_release);
  generation_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void PartRunner::run_erased(int parts, Call call, void* context, Order order) {
  if (workers_.empty()) {
    for (int thread = 1; thread < threads_; ++thread) workers_.emplace_back([this, thread] { work(thread); });
  }
  call_ = call;
  context_ = context;
  parts_ = parts;
  order_ = order;
  next_part_.store(0, std::memory_order_relaxed);
  busy_workers_.store(threads_ - 1, std::memory_order_relaxed);
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  run_my_parts(0);
  for (int busy = busy_workers_.load(std::memory_order_acquire); busy != 0;)
    busy = wait_for_change(busy_workers_, busy);
}

void PartRunner::work(int thread) {
  std::uint64_t seen = 0;
  while (true) {
    seen = wait_for_change(generation_, seen);
    if (seen == kStop) return;
    run_my_parts(thread);
    if (busy_workers_.fetch_sub(1, std::memory_order_acq_rel) == 1) busy_workers_.notify_one();
  }
}

void PartRunner::run_my_parts(int thread) {
  if (order_ == Order::AnyThread) {
    for (int part; (part = next_part_.fetch_add(1, std::memory_order_relaxed)) < parts_;) call_(context_, part);
    return;
  }
  for (int part = thread; part < parts_; part += threads_) call_(context_, part);
}

}  // namespace sim
