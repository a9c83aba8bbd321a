#include "cyber/plant/sim_options.hpp"

#include "number_text.hpp"

namespace cyber::plant {

namespace {

constexpr std::string_view kUsage =
    "usage: cyber-plant-sim [options]\n"
    "Simulates the elevator and arm motor controllers on a CAN interface: follows the setpoint\n"
    "frames of docs/can-protocol.md, publishes ARM_STATE on LCM and sends the roboRIO heartbeat.\n"
    "  --config FILE            robot and daemon config (default: the embedded reference robot)\n"
    "  --can IFACE              CAN interface (default: the config's [daemon] can_interface)\n"
    "  --lcm-url URL            LCM URL (default: the config's [daemon] lcm_url)\n"
    "  --initial T,THETA        initial elevator m and arm rad (default 0.2,1.57)\n"
    "  --coral, --algae         game pieces reported as held in ARM_STATE\n"
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
    "  --elevator-gains KP,KD   elevator PD gains, V/m and V/(m/s) (default 150,1)\n"
    "  --arm-gains KP,KD        arm PD gains, V/rad and V/(rad/s) (default 60,0.1)\n"
    "  --realtime PRIO          run under SCHED_FIFO at PRIO 1..99 (needs CAP_SYS_NICE; tests\n"
    "                           use it so the heartbeat keeps its period on a busy machine)\n"
    "  --help                   this text\n"
    "Exit status: 0 after a clean stop, 1 on a run-time failure (CAN or LCM could not be opened),\n"
    "2 on bad usage or an invalid config.\n";

SimArguments failure(std::string message) {
  SimArguments result;
  result.error = std::move(message);
  return result;
}

std::optional<PdGains> parseGains(std::string_view text) {
  const auto values = parseNumberList(text, 2);
  if (!values || (*values)[0] < 0.0 || (*values)[1] < 0.0) return std::nullopt;
  return PdGains{(*values)[0], (*values)[1]};
}

}  // namespace

std::string_view simUsage() { return kUsage; }

SimArguments parseSimArguments(const std::vector<std::string_view>& args) {
  SimArguments result;
  SimOptions& o = result.options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string_view arg = args[i];
    const auto value = [&]() -> std::optional<std::string_view> {
      if (i + 1 >= args.size()) return std::nullopt;
      return args[++i];
    };
    const auto missing = [&] { return failure(std::string(arg) + " needs a value"); };
    if (arg == "--help" || arg == "-h") {
      result.help = true;
      return result;
    } else if (arg == "--coral") {
      o.held_coral = true;
    } else if (arg == "--algae") {
      o.held_algae = true;
    } else if (arg == "--no-heartbeat") {
      o.heartbeat = false;
    } else if (arg == "--config" || arg == "--can" || arg == "--lcm-url" || arg == "--log" ||
               arg == "--control") {
      const auto v = value();
      if (!v) return missing();
      if (v->empty()) return failure(std::string(arg) + " must not be empty");
      auto& slot = arg == "--config"    ? o.config_path
                   : arg == "--can"     ? o.can_interface
                   : arg == "--log"     ? o.log_path
                   : arg == "--control" ? o.control_path
                                        : o.lcm_url;
      slot = std::string(*v);
    } else if (arg == "--initial") {
      const auto v = value();
      if (!v) return missing();
      const auto q = parseNumberList(*v, 2);
      if (!q) return failure("--initial must be T,THETA (elevator m, arm rad), got '" + std::string(*v) + "'");
      o.initial_q = planner::JointVector((*q)[0], (*q)[1]);
    } else if (arg == "--state-rate") {
      const auto v = value();
      if (!v) return missing();
      const auto hz = parseNumber(*v);
      if (!hz || *hz < 1.0 || *hz > 1000.0) return failure("--state-rate must be 1..1000 Hz, got '" + std::string(*v) + "'");
      o.state_rate_hz = *hz;
    } else if (arg == "--fault") {
      const auto v = value();
      if (!v) return missing();
      auto parsed = parseFault(*v);
      if (!parsed.event) return failure("--fault: " + parsed.error);
      o.faults.push_back(*parsed.event);
    } else if (arg == "--duration" || arg == "--setpoint-timeout") {
      const auto v = value();
      if (!v) return missing();
      const auto s = parseNumber(*v);
      if (!s || *s < 0.0 || (arg == "--setpoint-timeout" && *s <= 0.0)) {
        return failure(std::string(arg) + " must be a number of seconds" +
                       (arg == "--duration" ? " >= 0" : " > 0") + ", got '" + std::string(*v) + "'");
      }
      (arg == "--duration" ? o.duration_s : o.setpoint_timeout_s) = *s;
    } else if (arg == "--elevator-gains" || arg == "--arm-gains") {
      const auto v = value();
      if (!v) return missing();
      const auto gains = parseGains(*v);
      if (!gains) return failure(std::string(arg) + " must be KP,KD with both >= 0, got '" + std::string(*v) + "'");
      (arg == "--arm-gains" ? o.arm_gains : o.elevator_gains) = *gains;
    } else if (arg == "--realtime") {
      const auto v = value();
      if (!v) return missing();
      const auto prio = parseNumber(*v);
      if (!prio || *prio < 1.0 || *prio > 99.0 || *prio != static_cast<int>(*prio)) {
        return failure("--realtime must be a priority 1..99, got '" + std::string(*v) + "'");
      }
      o.realtime_priority = static_cast<int>(*prio);
    } else {
      return failure("unknown argument '" + std::string(arg) + "'");
    }
  }
  return result;
}

}  // namespace cyber::plant
