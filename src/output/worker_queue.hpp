// A bounded queue of jobs that one worker thread consumes in order: what the PNG and video writers run on,
// so that rendering the next frame overlaps writing the last one while memory stays bounded.
#pragma once

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace output {

template <class Job>
class WorkerQueue {
 public:
  using Consume = std::function<void(Job&)>;

  // At most `capacity` jobs wait (push() blocks beyond that); the worker calls consume(job) for each, in
  // order. The first exception consume() throws is kept: the jobs still queued are dropped, later ones are
  // refused, and push() or finish() rethrow it.
  WorkerQueue(std::size_t capacity, Consume consume)
      : capacity_(std::max<std::size_t>(capacity, 1)), consume_(std::move(consume)), thread_([this] { run(); }) {}
  // Drops what is still queued and joins the worker (call finish() first to have everything consumed).
  ~WorkerQueue() { stop(/*drop_queue=*/true); }
  WorkerQueue(const WorkerQueue&) = delete;
  WorkerQueue& operator=(const WorkerQueue&) = delete;

  // Queues `job`, waiting while the queue is full. Rethrows the error of an earlier job (once).
  void push(Job job) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return queue_.size() < capacity_ || error_; });
    rethrow_error_locked();
    queue_.push_back(std::move(job));
    changed_.notify_all();
  }

  // Waits until every queued job is consumed and joins the worker; rethrows the first error (once).
  void finish() {
    stop(/*drop_queue=*/false);
    std::unique_lock lock(mutex_);
    rethrow_error_locked();
  }

  // Drops the queued jobs and joins the worker.
  void abandon() { stop(/*drop_queue=*/true); }

  // True when a job failed (its error not yet rethrown).
  bool failed() const {
    std::unique_lock lock(mutex_);
    return static_cast<bool>(error_);
  }

  // A job the worker is done with, to reuse its storage (e.g. an image's pixels); nothing when none is free.
  std::optional<Job> spare() {
    std::unique_lock lock(mutex_);
    if (spares_.empty()) return std::nullopt;
    Job job = std::move(spares_.back());
    spares_.pop_back();
    return job;
  }

 private:
  void run() {
    for (;;) {
      Job job;
      {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [this] { return !queue_.empty() || closing_; });
        if (queue_.empty()) return;  // closing and drained
        job = std::move(queue_.front());
        queue_.pop_front();
        changed_.notify_all();  // room for the next job
      }
      try {
        consume_(job);
        std::unique_lock lock(mutex_);
        if (spares_.size() < capacity_) spares_.push_back(std::move(job));
      } catch (...) {
        std::unique_lock lock(mutex_);
        if (!error_) error_ = std::current_exception();
        queue_.clear();  // the run is failing: nothing after a failed job
        changed_.notify_all();
      }
    }
  }

  void stop(bool drop_queue) {
    {
      std::unique_lock lock(mutex_);
      if (drop_queue) queue_.clear();
      closing_ = true;
      changed_.notify_all();
    }
    if (thread_.joinable()) thread_.join();
  }

  void rethrow_error_locked() {
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  }

  const std::size_t capacity_;
  Consume consume_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> queue_;
  std::vector<Job> spares_;
  bool closing_ = false;
  std::exception_ptr error_;
  std::thread thread_;  // last: starts after everything it uses exists
};

}  // namespace output
