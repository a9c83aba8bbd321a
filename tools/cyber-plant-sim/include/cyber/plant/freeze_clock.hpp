#pragma once
// Simulation time that leaves out the time the simulator stood still. It wakes at least once per
// ARM_STATE period; a wake later than that period plus a tolerance means the process was not
// running (in the emulated test guest: the whole VM stood still, the daemon with it). The
// mechanism stands still too, instead of timing out and sliding in neutral for the lost time,
// which real controllers on their own hardware would never have seen.

namespace cyber::plant {

class FreezeClock {
 public:
  FreezeClock(double wake_interval_s, double tolerance_s) : interval_s_(wake_interval_s), tolerance_s_(tolerance_s) {}

  // At each wake, with the real time since start-up (non-decreasing); returns the simulation
  // time, which advances by at most one interval across a freeze.
  double onWake(double real_s);
  [[nodiscard]] double simulationTime(double real_s) const { return real_s - frozen_s_; }
  [[nodiscard]] int freezes() const { return freezes_; }
  [[nodiscard]] double frozenSeconds() const { return frozen_s_; }

 private:
  double interval_s_;
  double tolerance_s_;
  double last_real_s_ = 0.0;
  double frozen_s_ = 0.0;
  int freezes_ = 0;
};

}  // namespace cyber::plant
