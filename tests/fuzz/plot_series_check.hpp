#pragma once
// What both cyber-plot reader targets check of a result.

#include <string>

#include "cyber/plot/trajectory_plot.hpp"
#include "fuzz_check.hpp"

namespace cyber::fuzz {

// A failure has a message; a success gives equally long series with at least one sample.
inline void checkPlotResult(bool ok, const plot::TrajectoryPlotData& plot, const std::string& error) {
  if (!ok) {
    CYBER_FUZZ_CHECK(!error.empty());
    return;
  }
  CYBER_FUZZ_CHECK(!plot.time_s.empty());
  for (const auto& joint : plot.joints) {
    CYBER_FUZZ_CHECK(joint.position.size() == plot.time_s.size() && joint.velocity.size() == plot.time_s.size() &&
                     joint.volts.size() == plot.time_s.size() && joint.amps.size() == plot.time_s.size());
  }
}

}  // namespace cyber::fuzz
