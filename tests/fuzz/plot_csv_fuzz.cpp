// Fuzz target: cyber-plot's reader of cyber-plan CSVs (readPlanCsv) on a file with the input.
// Properties: no crash, hang, leak or UB; a failure has a message; a success gives equally long
// series with at least one sample.

#include "fuzz_file.hpp"
#include "plot_series_check.hpp"
#include "trajectory_sources.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > (1u << 20)) return 0;
  static cyber::fuzz::FuzzFile file;
  // The reference robot's joint names, as its corpus's headers spell the columns.
  static const cyber::planner::JointChain joints = [] {
    cyber::planner::JointChain chain(2);
    chain[0].name = "elevator";
    chain[1].name = "arm";
    return chain;
  }();
  cyber::fuzz::checkPlotResult(cyber::tools::readPlanCsv(file.write(data, size), joints));
  return 0;
}
