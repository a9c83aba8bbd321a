#include "cyber/plant/freeze_clock.hpp"

namespace cyber::plant {

double FreezeClock::onWake(double real_s) {
  const double gap_s = real_s - last_real_s_;
  if (gap_s > interval_s_ + tolerance_s_) {
    frozen_s_ += gap_s - interval_s_;
    ++freezes_;
  }
  last_real_s_ = real_s;
  return simulationTime(real_s);
}

}  // namespace cyber::plant
