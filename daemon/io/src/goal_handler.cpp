#include "cyber/daemon/io/goal_handler.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include "cyber/daemon/io/lcm_messages.hpp"
#include "cyber/daemon/io/monotonic_clock.hpp"

namespace cyber::daemon::io {

GoalHandler::GoalHandler(const planner::RobotModel& robot, const Settings& settings, LcmBridge& bridge,
                         PlanningWorker& worker, StreamerChannels& channels, EventLoop& loop)
    : robot_(robot),
      bridge_(bridge),
      worker_(worker),
      channels_(channels),
      loop_(loop),
      trajectories_(bridge, settings.trajectory_step_s, static_cast<int>(robot.joints.size())),
      coordinator_(robot, settings.coordinator, *this) {}

void GoalHandler::onGoal(const GoalRequest& goal, MonoNs now, GateVerdict gate) {
  goal_received_ns_[goal.request_id] = now;
  spdlog::debug("goal {}: {}, pieces [{}], scene '{}' at {} m", goal.request_id,
                goal.pose_name.empty() ? fmt::format("[{}]", fmt::join(goal.position, ", ")) : goal.pose_name,
                fmt::join(goal.pieces, ", "), goal.scene_name, goal.scene_offset_m);
  coordinator_.onGoal(goal, now, gate);
}

void GoalHandler::onCancel(const CancelRequest& cancel, MonoNs now) {
  spdlog::debug("ARM_CANCEL {} for request {}", cancel.action == CancelAction::kHold ? "hold" : "release",
                cancel.request_id);
  coordinator_.onCancel(cancel, now);
}

void GoalHandler::onPlanDone() {
  auto outcome = worker_.takeResult();
  if (!outcome) return;
  plan_times_.record(outcome->plan_time_s * 1e6);
  coordinator_.onPlanResult(outcome->job_id, std::move(outcome->result), outcome->plan_time_s, monotonicNow());
}

void GoalHandler::onStreamEvent(const StreamEvent& event, MonoNs now) {
  if (event.kind == StreamEventKind::kExecuting) {
    if (auto it = goal_received_ns_.find(event.request_id); it != goal_received_ns_.end()) {
      goal_latency_.record(nsToSeconds(event.time_ns - it->second) * 1e6);
      spdlog::debug("request {}: first setpoint {:.2f} ms after the goal arrived", event.request_id,
                    nsToMs(event.time_ns - it->second));
    }
  } else if (event.kind == StreamEventKind::kStopped) {
    // A release is asked for (ARM_CANCEL): not a fault.
    if (event.gate_reason == GateReason::kReleased) {
      spdlog::info("streaming stopped: {}", toString(event.gate_reason));
    } else {
      spdlog::warn("motion stopped: {}", toString(event.gate_reason));
    }
  } else if (event.kind == StreamEventKind::kHolding) {
    std::string where;
    for (int j = 0; j < robot_.jointCount() && j < event.position.size(); ++j) {
      where += fmt::format("{}{} {:.4f} {}", j == 0 ? "" : ", ", robot_.joints[j].name, event.position[j],
                           planner::unitName(robot_.joints[j].type));
    }
    spdlog::info("holding {} ({})", where, event.hold_cause == HoldCause::kShutdown ? "shutdown" : "motion allowed");
  }
  coordinator_.onStreamEvent(event, now);
}

void GoalHandler::onTimer(MonoNs now) {
  coordinator_.onTimer(now);
  trajectories_.flush(now);
}

void GoalHandler::publishStatus(const StatusUpdate& update) {
  bridge_.publish(bridge_.channels().plan_status, statusMessage(update, wallMicros()));
  const auto id = update.request_id;
  switch (update.status) {
    case GoalStatus::kRejected:
    case GoalStatus::kFailed:
      last_goal_failed_ = true;
      reject_warning_.warn(monotonicNow(), "request {} {}: {}", id, toString(update.status), update.reason);
      break;
    case GoalStatus::kExecuting:
      spdlog::info("request {} executing ({:.3f} s, planned in {:.1f} ms)", id, update.duration_s,
                   update.times_ms.total);
      break;
    case GoalStatus::kDone:
      last_goal_failed_ = false;
      spdlog::info("request {} done", id);
      break;
    default:
      spdlog::debug("request {} {}{}{}", id, toString(update.status), update.reason.empty() ? "" : ": ", update.reason);
      break;
  }
  if (isFinal(update.status)) goal_received_ns_.erase(id);
}

void GoalHandler::publishTrajectory(std::int64_t request_id, const SharedSetpointSource& trajectory, MonoNs start_ns) {
  trajectories_.offer(request_id, trajectory, start_ns, monotonicNow());
}

void GoalHandler::startPlanning(const PlanJob& job) { worker_.submit(job); }

void GoalHandler::postProgram(std::unique_ptr<Program> program) {
  const std::uint64_t id = program->id;
  Program* unread = channels_.offered.exchange(program.release(), std::memory_order_acq_rel);
  if (unread != nullptr) {
    // The coordinator waits for each program's answer, so this is not expected; answer for the
    // streamer so the coordinator does not wait forever.
    spdlog::error("program {} replaced program {} before the streamer read it", id, unread->id);
    StreamEvent rejected;
    rejected.kind = StreamEventKind::kRejected;
    rejected.program_id = unread->id;
    rejected.reject_reason = RejectReason::kStaleBase;
    delete unread;
    loop_.post([this, rejected] { coordinator_.onStreamEvent(rejected, monotonicNow()); });
  }
}

void GoalHandler::setReleaseGeneration(std::uint32_t generation) {
  channels_.release_generation.store(generation, std::memory_order_relaxed);
}

void GoalHandler::note(NoteLevel level, const std::string& text) {
  switch (level) {
    case NoteLevel::kDebug: spdlog::debug("{}", text); break;
    case NoteLevel::kInfo: spdlog::info("{}", text); break;
    case NoteLevel::kWarn: spdlog::warn("{}", text); break;
  }
}

}  // namespace cyber::daemon::io
