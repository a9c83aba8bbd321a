// cyber-wpilog: an lcm-logger log of a cyber-planner session as a WPILOG file for AdvantageScope
// (docs/operations.md, "AdvantageScope"), and a listing of any .wpilog. Exit: 0 done, 2 bad input.

#include <fmt/format.h>

#include <cstdio>
#include <string>
#include <vector>

#include "cyber/cli/usage_exit.hpp"
#include "cyber/config/load_config.hpp"
#include "cyber/wpilog/lcm_to_wpilog.hpp"
#include "cyber/wpilog/wpilog_reader.hpp"
#include "wpilog_arguments.hpp"

namespace {

int fail(const std::string& message) {
  std::fprintf(stderr, "cyber-wpilog: %s\n", message.c_str());
  return cyber::cli::kExitBadUsage;
}

std::string lastValue(const cyber::wpilog::Log& log, const cyber::wpilog::Entry& entry,
                      const cyber::wpilog::Record& r) {
  using namespace cyber::wpilog;
  const auto p = log.payload(r);
  if (entry.type == "double" && asDouble(p)) return fmt::format("{:.9g}", *asDouble(p));
  if (entry.type == "int64" && asInt64(p)) return std::to_string(*asInt64(p));
  if (entry.type == "boolean" && asBoolean(p)) return *asBoolean(p) ? "true" : "false";
  if (entry.type == "string" || entry.type == "json") return fmt::format("\"{}\"", asString(p));
  if (entry.type == "double[]" && asDoubleArray(p)) return fmt::format("[{} doubles]", asDoubleArray(p)->size());
  return fmt::format("({} bytes)", p.size());
}

int list(const std::string& path) {
  using namespace cyber::wpilog;
  const auto result = readFile(path);
  if (!result) return fail(result.error().message);
  const Log& log = result.value();
  std::vector<size_t> count(log.entries.size(), 0);
  std::vector<const Record*> last(log.entries.size(), nullptr);
  for (const Record& r : log.records) {
    ++count[r.entry];
    last[r.entry] = &r;
  }
  std::printf("%s: WPILOG %d.%d, \"%s\", %zu entries, %zu records\n", path.c_str(), log.version >> 8,
              log.version & 0xff, log.extra_header.c_str(), log.entries.size(), log.records.size());
  int undecodable = 0;
  for (size_t i = 0; i < log.entries.size(); ++i) {
    const Entry& e = log.entries[i];
    for (const Record* r : log.recordsOf(i)) undecodable += decodesAs(e.type, log.payload(*r)) ? 0 : 1;
    std::printf("%s\t%s\t%zu\t%s\n", e.name.c_str(), e.type.c_str(), count[i],
                last[i] != nullptr ? lastValue(log, e, *last[i]).c_str() : "");
  }
  if (undecodable > 0)
    return fail(path + ": " + std::to_string(undecodable) + " records do not decode as their entry's type");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace cyber;
  const auto parsed = tools::parseWpilogArguments(std::vector<std::string>(argv + 1, argv + argc));
  if (const auto status = cli::exitBeforeWork(parsed, {"cyber-wpilog", tools::wpilogUsage()})) return *status;
  const tools::WpilogArguments& args = parsed.value();
  if (!args.list_path.empty()) return list(args.list_path);

  config::Config config;
  try {
    config = args.config_path.empty() ? config::loadEmbeddedDefaultConfig() : config::loadConfigFile(args.config_path);
  } catch (const config::ConfigError& e) {
    return fail(e.what());
  }
  const auto conversion =
      wpilog::convertLcmLog(args.lcm_log_path, config.daemon.channels, wpilog::mechanismGeometry(config.robot));
  if (!conversion) return fail(conversion.error().message);
  if (const auto written = conversion->writer.writeFile(args.wpilog_path); !written) {
    return fail(written.error().message);
  }
  const wpilog::ConvertStats& stats = conversion->stats;
  std::printf("cyber-wpilog: %lld of %lld events converted (%lld undecodable, %lld on other channels) -> %s\n",
              static_cast<long long>(stats.converted), static_cast<long long>(stats.events),
              static_cast<long long>(stats.undecodable), static_cast<long long>(stats.other), args.wpilog_path.c_str());
  // A log of another robot converts without error but without its joints (docs/operations.md,
  // "AdvantageScope"): say so, since the likely cause is a missing or wrong --config.
  if (stats.other_joint_count > 0) {
    std::fprintf(stderr,
                 "cyber-wpilog: %lld messages have another joint count than the %d-joint robot of %s: their joint "
                 "values are left out (is --config the robot that was logged?)\n",
                 static_cast<long long>(stats.other_joint_count), config.robot.jointCount(),
                 args.config_path.empty() ? "the embedded config/reefscape-2025.toml" : args.config_path.c_str());
  }
  return 0;
}
