// Fork-join over a fixed number of parts on a few threads: the caller runs part 0 (and every
// threads-th after it), persistent workers run the others; or each thread takes the next part not yet taken
// (Order::AnyThread). Waiting polls briefly, then polls with yields (so a busy core still runs its other
// threads), then sleeps on a futex.
#pragma once

#include <atomic>
#include <cstdint>
#include <thread>
#include <type_traits>
#include <vector>

namespace sim {

class PartRunner {
 public:
  // `threads` >= 1 in all, the caller's included; workers start on the first run() that needs them.
  explicit PartRunner(int threads) : threads_(threads < 1 ? 1 : threads) {}
  ~PartRunner();
  PartRunner(const PartRunner&) = delete;
  PartRunner& operator=(const PartRunner&) = delete;

  int threads() const { return threads_; }

  // Which thread runs which part: ByThread, part p on thread p mod threads() (thread 0: the caller), for parts that
  // keep to a thread's own data from job to job; AnyThread, each thread takes the next part not yet taken, for parts
  // of unequal cost whose results do not depend on the thread.
  enum class Order { ByThread, AnyThread };

  // Calls body(part) once for every part in 0 .. parts - 1 and returns when all have returned. `body` must not throw.
  template <class Body>
  void run(int parts, Body&& body, Order order = Order::ByThread) {
    if (threads_ == 1 || parts == 1) {
      for (int part = 0; part < parts; ++part) body(part);
      return;
    }
    using Callable = std::remove_reference_t<Body>;
    run_erased(
        parts, [](void* context, int part) { (*static_cast<Callable*>(context))(part); }, &body, order);
  }

 private:
  using Call = void (*)(void* context, int part);
  void run_erased(int parts, Call call, void* context, Order order);
  void work(int thread);  // a worker's loop
  void run_my_parts(int thread);

  int threads_;
  std::vector<std::thread> workers_;
  // The job: written by the caller before `generation_` is bumped (release), read by workers after (acquire).
  Call call_ = nullptr;
  void* context_ = nullptr;
  int parts_ = 0;
  Order order_ = Order::ByThread;
  alignas(64) std::atomic<int> next_part_{0};  // Order::AnyThread: the next part to take
  std::atomic<std::uint64_t> generation_{0};   // bumped once per job; ~0: stop
  std::atomic<int> busy_workers_{0};           // workers still running their parts of the current job
};

}  // namespace sim
