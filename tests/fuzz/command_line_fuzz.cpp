// Fuzz target: the command-line parsers of cyber-plannerd, cyber-plan, cyber-goal and
// cyber-plant-sim, each on the same argument list (the input cut at NUL bytes and newlines).
// Properties: no crash, hang or UB; every rejection carries a message; what cyber-plan,
// cyber-goal and cyber-plant-sim accept is usable (finite poses, a positive timeout, rates in range).

#include <algorithm>
#include <cmath>
#include <string_view>

#include "cyber/cli/number_text.hpp"

#include "cyber/daemon/io/command_line.hpp"
#include "cyber/plant/sim_options.hpp"
#include "fuzz_check.hpp"
#include "fuzz_input.hpp"
#include "goal_arguments.hpp"
#include "plan_arguments.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return 0;
  const std::vector<std::string> args =
      cyber::fuzz::splitArguments(std::string_view(reinterpret_cast<const char*>(data), size));

  // (Without --config the daemon uses its embedded robot, so any accepted line is usable.)
  const auto daemon = cyber::daemon::io::parseCommandLine(args);
  if (!daemon) CYBER_FUZZ_CHECK(!daemon.error().message.empty());

  const auto plan = cyber::tools::parsePlanArguments(args);
  if (!plan) {
    CYBER_FUZZ_CHECK(!plan.error().message.empty());
  } else {
    const auto finite = [](const cyber::tools::PoseArgument& pose) {
      return std::all_of(pose.values.begin(), pose.values.end(), [](double v) { return std::isfinite(v); });
    };
    CYBER_FUZZ_CHECK(plan->help || (finite(plan->from) && finite(plan->to) && plan->from_velocity.allFinite()));
  }
  for (const auto& arg : args) {
    if (const auto pair = cyber::cli::parseNumberPair(arg))
      CYBER_FUZZ_CHECK(std::isfinite((*pair)[0]) && std::isfinite((*pair)[1]));
  }

  const auto goal = cyber::tools::parseGoalArguments(args);
  if (!goal) {
    CYBER_FUZZ_CHECK(!goal.error().message.empty());
  } else {
    CYBER_FUZZ_CHECK(goal->help || (goal->timeout_s > 0.0 && std::isfinite(goal->timeout_s)));
  }

  const auto sim = cyber::plant::parseSimArguments(args);
  if (sim && !sim->help) {
    CYBER_FUZZ_CHECK(sim->options.state_rate_hz >= 1.0 && sim->options.state_rate_hz <= 1000.0);
    CYBER_FUZZ_CHECK(!sim->options.initial_q || sim->options.initial_q->allFinite());
  }
  return 0;
}
