// Fuzz target: outside bytes as every LCM message type through safeDecode (the daemon's, the
// peers' and cyber-plot's decoder), and the decoded goal and state through the daemon's checks.
// Properties: safeDecode never reads past the buffer nor throws (ASan, libFuzzer); a decoded
// message re-encodes to bytes that decode to the same bytes again; validateGoal and
// stateFromMessage accept only finite values within the robot's limits.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

#include "cyber/config/load_config.hpp"
#include "cyber/daemon/goal_request.hpp"
#include "cyber/daemon/io/lcm_messages.hpp"
#include "cyber/lcmtypes/safe_decode.hpp"
#include "cyberplanner/arm_daemon_status_t.hpp"
#include "cyberplanner/arm_goal_t.hpp"
#include "cyberplanner/arm_plan_status_t.hpp"
#include "cyberplanner/arm_setpoint_t.hpp"
#include "cyberplanner/arm_state_t.hpp"
#include "cyberplanner/arm_trajectory_t.hpp"
#include "fuzz_check.hpp"

namespace {

const cyber::planner::RobotModel& robot() {
  static const cyber::config::Config config = cyber::config::loadEmbeddedDefaultConfig();
  return config.robot;
}

template <class Message>
std::vector<std::uint8_t> encode(const Message& message) {
  std::vector<std::uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()));
  CYBER_FUZZ_CHECK(message.encode(bytes.data(), 0, static_cast<int>(bytes.size())) == static_cast<int>(bytes.size()));
  return bytes;
}

// LCM sizes a string by its length but encodes it only up to its first NUL: such a message does
// not round-trip (lcm-gen's limit), and the daemon must never send one (checkGoal).
bool hasNul(const std::string& text) { return text.find('\0') != std::string::npos; }
template <class Strings>
bool anyHasNul(const Strings& texts) {
  return std::any_of(std::begin(texts), std::end(texts), [](const std::string& text) { return hasNul(text); });
}
template <class Message>
bool stringsRoundTrip(const Message&) {
  return true;
}
bool stringsRoundTrip(const cyberplanner::arm_goal_t& m) {
  return !hasNul(m.pose_name) && !hasNul(m.scene_name) && !anyHasNul(m.pieces);
}
bool stringsRoundTrip(const cyberplanner::arm_state_t& m) { return !anyHasNul(m.pieces); }
bool stringsRoundTrip(const cyberplanner::arm_plan_status_t& m) { return !hasNul(m.reason); }
bool stringsRoundTrip(const cyberplanner::arm_daemon_status_t& m) {
  return !anyHasNul(m.joint_names) && !anyHasNul(m.joint_units);
}

// Decodes; on success checks the round trip and returns true with the message in `out`.
template <class Message>
bool decodeRoundTrip(const std::uint8_t* data, int size, Message& out) {
  const int used = cyber::lcmtypes::safeDecode(out, data, size);
  if (used < 0) return false;
  CYBER_FUZZ_CHECK(used <= size);
  if (!stringsRoundTrip(out)) return true;
  const std::vector<std::uint8_t> bytes = encode(out);
  CYBER_FUZZ_CHECK(static_cast<int>(bytes.size()) == used);
  Message again{};
  CYBER_FUZZ_CHECK(cyber::lcmtypes::safeDecode(again, bytes.data(), static_cast<int>(bytes.size())) == used);
  CYBER_FUZZ_CHECK(encode(again) == bytes);
  return true;
}

void checkGoal(const cyberplanner::arm_goal_t& message) {
  const cyber::daemon::GoalRequest goal = cyber::daemon::io::goalFromMessage(message);
  const auto valid = cyber::daemon::validateGoal(goal, robot());
  if (!valid) {
    CYBER_FUZZ_CHECK(!valid.error().message.empty());
    // The answer the daemon publishes encodes to exactly the bytes it sends.
    cyber::daemon::StatusUpdate update;
    update.request_id = goal.request_id;
    update.status = cyber::daemon::GoalStatus::kRejected;
    update.reason = valid.error().message;
    const auto answer = cyber::daemon::io::statusMessage(update, 0);
    CYBER_FUZZ_CHECK(!hasNul(answer.reason));
    encode(answer);
    return;
  }
  const auto& v = valid.value();
  CYBER_FUZZ_CHECK(std::isfinite(v.q[0]) && std::isfinite(v.q[1]));
  CYBER_FUZZ_CHECK(robot().withinLimits(v.q, 0.0));
  CYBER_FUZZ_CHECK(v.scene >= 0 && v.scene < static_cast<int>(robot().scenes.size()));
  CYBER_FUZZ_CHECK(v.request_id == message.request_id);
}

void checkState(const cyberplanner::arm_state_t& message) {
  const auto state = cyber::daemon::io::stateFromMessage(message, robot());
  if (!state) return;
  CYBER_FUZZ_CHECK(state->q.allFinite() && state->qdot.allFinite());
  CYBER_FUZZ_CHECK(robot().withinLimits(state->q, 0.5));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > (1u << 20)) return 0;  // LCM's UDP transport carries at most 256 kB
  const int len = static_cast<int>(size);
  cyberplanner::arm_goal_t goal{};
  if (decodeRoundTrip(data, len, goal)) checkGoal(goal);
  cyberplanner::arm_state_t state{};
  if (decodeRoundTrip(data, len, state)) checkState(state);
  cyberplanner::arm_plan_status_t plan_status{};
  decodeRoundTrip(data, len, plan_status);
  cyberplanner::arm_trajectory_t trajectory{};
  if (decodeRoundTrip(data, len, trajectory)) {
    CYBER_FUZZ_CHECK(trajectory.num_samples >= 0 &&
                     trajectory.num_samples <= cyberplanner::arm_trajectory_t::MAX_SAMPLES);
    CYBER_FUZZ_CHECK(trajectory.t_s.size() == static_cast<size_t>(trajectory.num_samples));
  }
  cyberplanner::arm_setpoint_t setpoint{};
  decodeRoundTrip(data, len, setpoint);
  cyberplanner::arm_daemon_status_t daemon_status{};
  decodeRoundTrip(data, len, daemon_status);
  return 0;
}
