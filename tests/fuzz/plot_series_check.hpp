#pragma once
// What both cyber-plot reader targets check of a result.

#include "cyber/plot/trajectory_plot.hpp"
#include "cyber/result.hpp"
#include "fuzz_check.hpp"

namespace cyber::fuzz {

// A failure has a message; a success gives equally long series with at least one sample.
template <class Status>
void checkPlotResult(const Result<plot::TrajectoryPlotData, Status>& result) {
  if (!result) {
    CYBER_FUZZ_CHECK(!result.error().message.empty());
    return;
  }
  const plot::TrajectoryPlotData& plot = result.value();
  CYBER_FUZZ_CHECK(!plot.time_s.empty());
  for (const auto& joint : plot.joints) {
    CYBER_FUZZ_CHECK(joint.position.size() == plot.time_s.size() && joint.velocity.size() == plot.time_s.size() &&
                     joint.volts.size() == plot.time_s.size() && joint.amps.size() == plot.time_s.size());
  }
}

}  // namespace cyber::fuzz
