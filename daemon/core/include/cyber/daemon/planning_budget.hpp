#pragma once
// How far ahead of "now" a plan into a running motion starts: the measured planning time with
// headroom, never below the configured budget. The splice point must still be in the future when
// the plan reaches the streamer, so the streamer's period is added as a margin.

#include <array>
#include <cstddef>

namespace cyber::daemon {

class PlanningBudget {
 public:
  static constexpr std::size_t kWindow = 16;  // recent plans considered
  static constexpr double kHeadroom = 1.25;

  PlanningBudget(double configured_s, double margin_s, double max_s);

  void record(double plan_time_s);
  // max(configured, headroom * slowest recent plan + margin), capped at max_s.
  [[nodiscard]] double budgetS() const;
  // A plan is late when it is not back at least this long before its splice time.
  [[nodiscard]] double marginS() const { return margin_s_; }

 private:
  double configured_s_;
  double margin_s_;
  double max_s_;
  std::array<double, kWindow> recent_{};
  std::size_t count_ = 0;
  std::size_t next_ = 0;
};

}  // namespace cyber::daemon
