// Fuzz target: cyber-plot's reader of ARM_TRAJECTORY from an LCM log (readTrajectoryFromLog, with
// liblcm's log reader underneath) on a file with the input.
// Properties: no crash, hang, leak or UB; a failure has a message; a success gives equally long
// series with at least one sample.
// liblcm allocates the data length an event header states (up to 2 GiB) before it reads the data;
// under ASan each such allocation of a corrupt log takes up to a second (docs/testing.md).

#include "cyber/config/load_config.hpp"
#include "fuzz_file.hpp"
#include "plot_series_check.hpp"
#include "trajectory_sources.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > (1u << 20)) return 0;
  static const cyber::config::Config config = cyber::config::loadEmbeddedDefaultConfig();
  static cyber::fuzz::FuzzFile file;
  cyber::fuzz::checkPlotResult(
      cyber::tools::readTrajectoryFromLog(file.write(data, size), "ARM_TRAJECTORY", std::nullopt, config.robot));
  return 0;
}
