#include "cyber/daemon/io/planning_worker.hpp"

#include <chrono>

#include "cyber/daemon/io/monotonic_clock.hpp"
#include "cyber/daemon/io/thread_priority.hpp"

namespace cyber::daemon::io {

PlanningWorker::PlanningWorker(const PlanningService& service) : service_(service) {}

PlanningWorker::~PlanningWorker() {
  if (thread_.joinable()) {
    stop(1e9);
  }
}

void PlanningWorker::start() {
  thread_ = std::thread([this] { run(); });
}

void PlanningWorker::submit(const PlanJob& job) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job_ = job;
  }
  wake_.notify_one();
}

std::optional<PlanOutcome> PlanningWorker::takeResult() {
  done_.drain();
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<PlanOutcome> out = std::move(result_);
  result_.reset();
  return out;
}

bool PlanningWorker::stop(double timeout_s) {
  {
    std::unique_lock<std::mutex> lock(mutex_);
    quit_ = true;
    wake_.notify_one();
    if (!finished_.wait_for(lock, std::chrono::duration<double>(timeout_s), [this] { return !busy_; })) return false;
  }
  if (thread_.joinable()) thread_.join();
  return true;
}

void PlanningWorker::run() {
  // Planning takes whole milliseconds of CPU: at a real-time priority inherited from a creator
  // started with one, it would starve the machine.
  useNormalScheduling();
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return quit_ || job_.has_value(); });
    if (quit_) return;
    const PlanJob job = *job_;
    job_.reset();
    busy_ = true;
    lock.unlock();

    const MonoNs begin = monotonicNow();
    planner::Result<PlannedMotion> result = service_.plan(job.request);
    const double seconds = nsToSeconds(monotonicNow() - begin);

    lock.lock();
    busy_ = false;
    result_.emplace(PlanOutcome{job.job_id, std::move(result), seconds});
    finished_.notify_all();
    done_.signal();
  }
}

}  // namespace cyber::daemon::io
