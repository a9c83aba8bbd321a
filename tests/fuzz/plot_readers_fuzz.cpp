// Fuzz target: cyber-plot's readers on a file with the input's bytes after the first: a
// cyber-plan CSV when the first byte is even, an LCM log otherwise (the readers take paths, so
// the bytes go to a memfd opened by its /proc path).
// Properties: no crash, hang, leak or UB; a failure sets a message; a success yields equally long
// series with at least one sample.

#include <sys/mman.h>
#include <unistd.h>

#include <string>

#include "cyber/config/load_config.hpp"
#include "fuzz_check.hpp"
#include "trajectory_sources.hpp"

namespace {

const std::string& inputPath() {
  static const std::string path = [] {
    const int fd = memfd_create("cyber-plot-fuzz", 0);
    CYBER_FUZZ_CHECK(fd >= 0);
    return "/proc/self/fd/" + std::to_string(fd);
  }();
  return path;
}

void writeInput(const std::uint8_t* data, std::size_t size) {
  const int fd = std::stoi(inputPath().substr(std::string("/proc/self/fd/").size()));
  CYBER_FUZZ_CHECK(ftruncate(fd, 0) == 0);
  std::size_t written = 0;
  while (written < size) {
    const ssize_t n = pwrite(fd, data + written, size - written, static_cast<off_t>(written));
    CYBER_FUZZ_CHECK(n > 0);
    written += static_cast<std::size_t>(n);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0 || size > (1u << 20)) return 0;
  static const cyber::config::Config config = cyber::config::loadEmbeddedDefaultConfig();
  writeInput(data + 1, size - 1);
  cyber::plot::TrajectoryPlotData plot;
  std::string error;
  const bool ok = data[0] % 2 == 0
                      ? cyber::tools::readPlanCsv(inputPath(), plot, &error)
                      : cyber::tools::readTrajectoryFromLog(inputPath(), "ARM_TRAJECTORY", std::nullopt, config.robot,
                                                            plot, &error);
  if (!ok) {
    CYBER_FUZZ_CHECK(!error.empty());
    return 0;
  }
  CYBER_FUZZ_CHECK(!plot.time_s.empty());
  for (const auto& joint : plot.joints) {
    CYBER_FUZZ_CHECK(joint.position.size() == plot.time_s.size() && joint.velocity.size() == plot.time_s.size() &&
                     joint.volts.size() == plot.time_s.size() && joint.amps.size() == plot.time_s.size());
  }
  return 0;
}
