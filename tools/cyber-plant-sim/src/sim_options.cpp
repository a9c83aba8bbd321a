#include "cyber/plant/sim_options.hpp"

#include "cyber/cli/argument_parser.hpp"
#include "cyber/cli/number_text.hpp"

namespace cyber::plant {

namespace {

constexpr std::string_view kUsage =
    "usage: cyber-plant-sim [options]\n"
    "Simulates the motor controller of each of the config's joints on a CAN interface: follows\n"
    "the setpoint frames of docs/can-protocol.md, publishes ARM_STATE on LCM and sends the roboRIO\n"
    "heartbeat.\n"
    "  --config FILE            robot and daemon config (default: the embedded reference robot)\n"
    "  --can IFACE              CAN interface (default: the config's [daemon] can_interface)\n"
    "  --lcm-url URL            LCM URL (default: the config's [daemon] lcm_url)\n"
    "  --initial Q0[,Q1[,Q2]]   initial position of each joint, one per joint of the config (m or\n"
    "                           rad; default: the config's first named pose, else the middle of\n"
    "                           every range)\n"
    "  --pieces NAME[,NAME...]  game pieces reported as held in ARM_STATE (the config's names)\n"
    "  --state-rate HZ          ARM_STATE rate, 1..1000 (default 100)\n"
    "  --no-heartbeat           send no roboRIO heartbeat (id 0x01011840, 20 ms)\n"
    "  --fault KIND@WHEN        inject a fault; WHEN is SECONDS after start, or motionN+SECONDS\n"
    "                           after the N-th motion started (motion+ = motion1+; a motion starts\n"
    "                           with a non-zero velocity setpoint after rest); KIND is one of\n"
    "                           heartbeat-stop, heartbeat-resume, heartbeat-disabled,\n"
    "                           heartbeat-enabled, disable, silent, state-resume, exit\n"
    "  --control FIFO           apply the fault KINDs written to FIFO, one per line, at once\n"
    "                           (created if missing)\n"
    "  --log FILE               write the simulated state as CSV, one row per ARM_STATE period\n"
    "  --duration S             stop after S seconds (default: run until SIGINT/SIGTERM)\n"
    "  --setpoint-timeout S     controllers go neutral after S without a setpoint (default 0.1)\n"
    "  --bandwidth RADPS        closed-loop bandwidth the controllers' PD gains are derived for\n"
    "                           from the config's drives (default 100 rad/s)\n"
    "  --joint0-gains KP,KD     joint 0's PD gains instead, V/unit and V/(unit/s) (unit: m or rad)\n"
    "  --joint1-gains KP,KD     joint 1's PD gains instead\n"
    "  --joint2-gains KP,KD     joint 2's PD gains instead (a chain of three joints)\n"
    "  --realtime PRIO          run under SCHED_FIFO at PRIO 1..99 (needs CAP_SYS_NICE; tests\n"
    "                           use it so the heartbeat keeps its period on a busy machine)\n"
    "  --help                   this text\n"
    "Exit status: 0 after a clean stop, 1 on a run-time failure (CAN or LCM could not be opened),\n"
    "2 on bad usage or an invalid config.\n";

std::optional<PdGains> parseGains(std::string_view text) {
  const auto values = cli::parseNumberPair(text);
  if (!values || (*values)[0] < 0.0 || (*values)[1] < 0.0) return std::nullopt;
  return PdGains{(*values)[0], (*values)[1]};
}

// Seconds: > 0, or >= 0 when zero is allowed.
cli::ValueHandler seconds(double* into, bool zero_allowed) {
  return [into, zero_allowed](const std::string& value) -> std::string {
    const auto s = cli::parseNumber(value);
    if (!s || *s < 0.0 || (!zero_allowed && *s == 0.0)) {
      return std::string("must be a number of seconds") + (zero_allowed ? " >= 0" : " > 0") + ", got '" + value + "'";
    }
    *into = *s;
    return "";
  };
}

// "Q0[,Q1[,Q2]]": 1 to kMaxJoints finite numbers, one comma between each two. Whether there is one
// per joint is checked against the config once it is loaded.
std::optional<planner::JointVector> parseJointList(std::string_view text) {
  planner::JointVector q(0);
  while (true) {
    const std::size_t comma = text.find(',');
    const auto value = cli::parseNumber(text.substr(0, comma));
    if (!value || q.size() == kMaxJoints) return std::nullopt;
    q.conservativeResize(q.size() + 1);
    q[q.size() - 1] = *value;
    if (comma == std::string_view::npos) return q;
    text.remove_prefix(comma + 1);
  }
}

cli::ValueHandler gains(std::optional<PdGains>* into) {
  return [into](const std::string& value) -> std::string {
    const auto g = parseGains(value);
    if (!g) return "must be KP,KD with both >= 0, got '" + value + "'";
    *into = *g;
    return "";
  };
}

}  // namespace

std::string_view simUsage() { return kUsage; }

Result<SimArguments, cli::ArgumentStatus> parseSimArguments(const std::vector<std::string>& args) {
  SimArguments result;
  SimOptions& o = result.options;
  cli::ArgumentParser parser;
  parser.option("--pieces", [&](const std::string& v) -> std::string {
    o.pieces.clear();
    if (v.empty() || v == "none") return "";
    size_t from = 0;
    while (true) {
      const size_t end = v.find(',', from);
      const std::string name = v.substr(from, end == std::string::npos ? std::string::npos : end - from);
      if (name.empty()) return "must be NAME[,NAME...], got '" + v + "'";
      o.pieces.push_back(name);
      if (end == std::string::npos) break;
      from = end + 1;
    }
    if (o.pieces.size() > static_cast<size_t>(planner::HeldPieces::kMaxPieces)) {
      return "at most " + std::to_string(planner::HeldPieces::kMaxPieces) + " pieces, got '" + v + "'";
    }
    return "";
  });
  parser.flag("--no-heartbeat", [&] { o.heartbeat = false; });
  parser.option("--config", cli::store(o.config_path));
  parser.option("--can", cli::store(o.can_interface));
  parser.option("--lcm-url", cli::store(o.lcm_url));
  parser.option("--log", cli::store(o.log_path));
  parser.option("--control", cli::store(o.control_path));
  parser.option("--initial", [&](const std::string& v) -> std::string {
    const auto q = parseJointList(v);
    if (!q) return "must be Q0[,Q1[,Q2]] (one position per joint: m or rad), got '" + v + "'";
    o.initial_q = *q;
    return "";
  });
  parser.option("--state-rate", [&](const std::string& v) -> std::string {
    const auto hz = cli::parseNumber(v);
    if (!hz || *hz < 1.0 || *hz > 1000.0) return "must be 1..1000 Hz, got '" + v + "'";
    o.state_rate_hz = *hz;
    return "";
  });
  parser.option("--fault", [&](const std::string& v) -> std::string {
    auto parsed = parseFault(v);
    if (!parsed.event) return parsed.error;
    o.faults.push_back(*parsed.event);
    return "";
  });
  parser.option("--duration", seconds(&o.duration_s, true));
  parser.option("--setpoint-timeout", seconds(&o.setpoint_timeout_s, false));
  parser.option("--bandwidth", [&](const std::string& v) -> std::string {
    const auto radps = cli::parseNumber(v);
    if (!radps || *radps <= 0.0 || *radps > 1000.0) return "must be 0..1000 rad/s (not 0), got '" + v + "'";
    o.controller_bandwidth_radps = *radps;
    return "";
  });
  parser.option("--joint0-gains", gains(&o.joint_gains[0]));
  parser.option("--joint1-gains", gains(&o.joint_gains[1]));
  parser.option("--joint2-gains", gains(&o.joint_gains[2]));
  parser.option("--realtime", [&](const std::string& v) -> std::string {
    const auto prio = cli::parseInteger(v);
    if (!prio || *prio < 1 || *prio > 99) return "must be a priority 1..99, got '" + v + "'";
    o.realtime_priority = static_cast<int>(*prio);
    return "";
  });
  if (auto decided = parser.parseInto(args, result)) return *decided;
  return result;
}

}  // namespace cyber::plant
