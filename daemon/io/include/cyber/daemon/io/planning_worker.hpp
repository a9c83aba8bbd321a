#pragma once
// The planning worker thread: takes one job at a time from the event loop, runs the (blocking)
// planner and hands the result back, waking the loop through an eventfd. The coordinator never
// submits a second job before the first one's result, so one slot each way is enough.

#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>

#include "cyber/daemon/goal_coordinator.hpp"
#include "cyber/daemon/io/fd.hpp"
#include "cyber/daemon/planning_service.hpp"

namespace cyber::daemon::io {

struct PlanOutcome {
  std::uint64_t job_id = 0;
  planner::Result<PlannedMotion> result;
  double plan_time_s = 0.0;
};

class PlanningWorker {
 public:
  explicit PlanningWorker(const PlanningService& service);
  ~PlanningWorker();
  PlanningWorker(const PlanningWorker&) = delete;
  PlanningWorker& operator=(const PlanningWorker&) = delete;

  void start();
  void submit(const PlanJob& job);
  std::optional<PlanOutcome> takeResult();
  // Readable when a result is waiting.
  [[nodiscard]] int wakeFd() const { return done_.fd(); }
  // Asks the thread to end and waits up to `timeout_s` for a plan in progress; false if the
  // planner is still busy (the caller then exits without joining).
  bool stop(double timeout_s);

 private:
  void run();

  const PlanningService& service_;
  EventFd done_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable finished_;
  std::optional<PlanJob> job_;
  std::optional<PlanOutcome> result_;
  bool busy_ = false;
  bool quit_ = false;
  std::thread thread_;
};

}  // namespace cyber::daemon::io
