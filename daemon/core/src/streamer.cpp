#include "cyber/daemon/streamer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace cyber::daemon {

void TickOutput::reset() {
  send_setpoints = false;
  mode = StreamMode::kNoState;
  gate_reason = GateReason::kNoState;
  request_id = -1;
  segment_time_s = 0.0;
  remaining_s = 0.0;
  event_count = 0;
  retired_count = 0;
}

// Overflow is a defect of the streamer, never a run-time condition: a dropped event would leave the
// coordinator waiting for an answer, a dropped program would leak. Checked in every build (not an
// assert() that NDEBUG removes); abort() neither allocates nor blocks.
void TickOutput::push(const StreamEvent& event) {
  if (event_count >= kMaxEvents) std::abort();
  events[static_cast<size_t>(event_count++)] = event;
}

void TickOutput::retire(Program* program) {
  if (program == nullptr) return;
  if (retired_count >= kMaxRetired) std::abort();
  retired[static_cast<size_t>(retired_count++)] = program;
}

Streamer::Streamer(const HoldModel& hold, const StreamerSettings& settings) : hold_(hold), settings_(settings) {}

Streamer::~Streamer() {
  if (program_ != &own_) delete program_;
}

Program* Streamer::releaseProgram() {
  if (program_ == &own_) return nullptr;
  Program* released = program_;
  program_ = &own_;
  return released;
}

void Streamer::dropOwned(TickOutput& out) {
  if (program_ != &own_) out.retire(program_);
  program_ = &own_;
}

void Streamer::restartOwnHold(MonoNs now, const JointVector& q, StreamEvent event, TickOutput& out) {
  event.time_ns = now;
  event.request_id = executing_request_;
  event.position = q;
  dropOwned(out);
  ++epoch_;  // programs planned on the old epoch are stale from here on
  own_.resetToHold(epoch_, q);
  executing_request_ = -1;
  done_reported_ = true;
  event.epoch = epoch_;
  event.release_generation = releases_seen_;
  out.push(event);
}

void Streamer::stop(MonoNs now, GateReason reason, TickOutput& out) {
  StreamEvent event;
  event.kind = StreamEventKind::kStopped;
  event.gate_reason = reason;
  running_ = false;
  restartOwnHold(now, last_position_, event, out);
}

void Streamer::holdOwn(MonoNs now, const JointVector& q, HoldCause cause, TickOutput& out) {
  StreamEvent event;
  event.kind = StreamEventKind::kHolding;
  event.hold_cause = cause;
  restartOwnHold(now, q, event, out);
}

void Streamer::reject(MonoNs now, Program* offered, RejectReason reason, TickOutput& out) {
  StreamEvent event;
  event.kind = StreamEventKind::kRejected;
  event.time_ns = now;
  event.program_id = offered->id;
  event.epoch = epoch_;
  event.reject_reason = reason;
  out.retire(offered);
  out.push(event);
}

void Streamer::consider(MonoNs now, Program* offered, TickOutput& out) {
  StreamEvent event;
  event.time_ns = now;
  event.program_id = offered->id;
  event.epoch = epoch_;
  const bool same_base = offered->epoch == epoch_ && offered->base_id == program_->id && !shutdown_hold_;
  if (!same_base || (!offered->floating && offered->splice_ns <= last_sample_ns_)) {
    reject(now, offered, same_base ? RejectReason::kLate : RejectReason::kStaleBase, out);
    return;
  }
  offered->resolveFloatingStart(now);
  dropOwned(out);
  program_ = offered;
  event.kind = StreamEventKind::kAdopted;
  event.start_ns = offered->splice_ns;
  if (offered->segmentCount() > 0) event.request_id = offered->segment(offered->segmentCount() - 1).request_id;
  out.push(event);
}

bool Streamer::withinLimits(const JointSetpoints& s) const {
  const SetpointLimits& lim = settings_.limits;
  for (int j = 0; j < s.position.size(); ++j) {
    if (!(std::abs(s.position[j]) <= lim.position) || !(std::abs(s.velocity[j]) <= lim.velocity) ||
        !(std::abs(s.volts[j]) <= lim.volts)) {
      return false;  // also catches NaN
    }
  }
  return true;
}

GateVerdict Streamer::gate(MonoNs now, const RobotInputs& inputs) {
  GateVerdict verdict = evaluateGate(inputs, now, settings_.gate);
  // A disable this tick has not seen stops motion even when an enabled heartbeat already followed it.
  const bool new_disable = inputs.broadcast_disable_count != disables_seen_;
  disables_seen_ = inputs.broadcast_disable_count;
  if (verdict.open() && new_disable) verdict.reason = GateReason::kBroadcastDisable;
  // Likewise every change of the release generation stops the stream once: a release and the goal
  // that ends it within one period still restart the stream from the measured position.
  const bool new_release = inputs.release_generation != releases_seen_;
  releases_seen_ = inputs.release_generation;
  if (verdict.open() && new_release) verdict.reason = GateReason::kReleased;
  if (verdict.open() && now < fault_until_ns_) verdict.reason = GateReason::kFault;
  return verdict;
}

void Streamer::closedGate(MonoNs now, const GateVerdict& verdict, Program* offered, TickOutput& out) {
  if (running_) stop(now, verdict.reason, out);
  if (offered != nullptr) reject(now, offered, RejectReason::kStaleBase, out);
  out.mode = verdict.reason == GateReason::kFault      ? StreamMode::kFault
             : verdict.reason == GateReason::kReleased ? StreamMode::kReleased
             : isRobotDisabledReason(verdict.reason)   ? StreamMode::kRobotDisabled
                                                       : StreamMode::kNoState;
  out.request_id = last_request_;
}

void Streamer::sampleFault(MonoNs now, const ProgramSample& sample, TickOutput& out) {
  // Never send a wrapped or NaN value: stop streaming, then hold the measured position.
  StreamEvent fault;
  fault.kind = StreamEventKind::kFault;
  fault.time_ns = now;
  fault.request_id = sample.request_id;
  out.push(fault);
  fault_until_ns_ = now + secondsToNs(settings_.fault_stop_s);
  stop(now, GateReason::kFault, out);
  out.gate_reason = GateReason::kFault;
  out.mode = StreamMode::kFault;
  out.request_id = last_request_;
}

void Streamer::reportProgress(MonoNs now, const ProgramSample& sample, TickOutput& out) {
  if (sample.request_id >= 0 && sample.request_id != executing_request_) {
    const Segment& segment = program_->segment(sample.segment);
    if (executing_request_ >= 0 && !done_reported_ && executing_end_ns_ <= segment.start_ns) {
      // The previous motion ran to its end before this one took over (a start from rest).
      StreamEvent done;
      done.kind = StreamEventKind::kDone;
      done.time_ns = now;
      done.request_id = executing_request_;
      done.epoch = epoch_;
      out.push(done);
    }
    executing_request_ = sample.request_id;
    executing_end_ns_ = segment.start_ns + secondsToNs(segment.source->durationS());
    done_reported_ = false;
    StreamEvent event;
    event.kind = StreamEventKind::kExecuting;
    event.time_ns = now;
    event.request_id = sample.request_id;
    event.epoch = epoch_;
    out.push(event);
  }
  if (sample.request_id >= 0 && !sample.moving && sample.last_segment && !done_reported_) {
    done_reported_ = true;
    StreamEvent event;
    event.kind = StreamEventKind::kDone;
    event.time_ns = now;
    event.request_id = sample.request_id;
    event.position = sample.setpoints.position;
    event.epoch = epoch_;
    out.push(event);
  }
  if (sample.request_id >= 0) last_request_ = sample.request_id;
}

void Streamer::send(MonoNs now, const ProgramSample& sample, TickOutput& out) {
  last_sample_ns_ = now;
  last_position_ = sample.setpoints.position;
  out.send_setpoints = true;
  out.setpoints = sample.setpoints;
  out.mode = sample.moving ? StreamMode::kMoving : StreamMode::kHolding;
  out.request_id = last_request_;
  out.segment_time_s = sample.segment_time_s;
  const MonoNs end = program_->endNs();
  out.remaining_s = end == kNever ? 0.0 : std::max(0.0, nsToSeconds(end - now));
}

void Streamer::tick(MonoNs now, const RobotInputs& inputs, Program* offered, bool stop_requested, TickOutput& out) {
  out.reset();
  const GateVerdict verdict = gate(now, inputs);
  out.gate_reason = verdict.reason;
  if (!verdict.open()) {
    closedGate(now, verdict, offered, out);
    return;
  }
  if (!running_) {
    // (Re-)enabled: hold where the mechanism is, not where the last command was.
    running_ = true;
    holdOwn(now, inputs.measured_q, HoldCause::kEnabled, out);
  }
  if (stop_requested && !shutdown_hold_) {
    holdOwn(now, last_sample_ns_ == kNever ? inputs.measured_q : last_position_, HoldCause::kShutdown, out);
    shutdown_hold_ = true;
  }
  if (offered != nullptr) consider(now, offered, out);

  const ProgramSample sample = program_->sample(now, hold_);
  if (!withinLimits(sample.setpoints)) {
    sampleFault(now, sample, out);
    return;
  }
  reportProgress(now, sample, out);
  send(now, sample, out);
}

}  // namespace cyber::daemon
