#include "cyber/daemon/program.hpp"

#include <algorithm>

namespace cyber::daemon {

namespace {

MonoNs segmentEndNs(const Segment& segment) { return segment.start_ns + secondsToNs(segment.source->durationS()); }

}  // namespace

Program Program::holdAt(std::uint64_t epoch, const JointVector& q) {
  Program program;
  program.resetToHold(epoch, q);
  return program;
}

void Program::resetToHold(std::uint64_t epoch_value, const JointVector& q) {
  for (int i = 0; i < count_; ++i) segments_[static_cast<size_t>(i)] = Segment{};
  count_ = 0;
  id = 0;
  base_id = 0;
  epoch = epoch_value;
  rest_q = q;
  splice_ns = 0;
  floating = false;
}

MonoNs Program::endNs() const {
  return count_ == 0 ? kNever : segmentEndNs(segments_[static_cast<size_t>(count_ - 1)]);
}

JointVector Program::restPosition() const {
  if (count_ == 0) return rest_q;
  const Segment& last = segments_[static_cast<size_t>(count_ - 1)];
  return last.source->at(last.source->durationS()).position;
}

ProgramSample Program::sample(MonoNs t, const HoldModel& hold) const {
  ProgramSample out;
  int k = -1;
  for (int i = 0; i < count_; ++i) {
    if (segments_[static_cast<size_t>(i)].start_ns <= t) k = i;
  }
  if (k < 0) {
    out.setpoints = hold.hold(rest_q);
    return out;
  }
  const Segment& segment = segments_[static_cast<size_t>(k)];
  const double duration_s = segment.source->durationS();
  const double tau_s = nsToSeconds(t - segment.start_ns);
  out.segment = k;
  out.request_id = segment.request_id;
  out.last_segment = k == count_ - 1;
  if (tau_s < duration_s) {
    out.setpoints = segment.source->at(tau_s);
    out.segment_time_s = tau_s;
    out.moving = true;
  } else {
    // Past the end: hold the end position with the gravity feedforward only.
    out.setpoints = hold.hold(segment.source->at(duration_s).position);
    out.segment_time_s = duration_s;
  }
  return out;
}

void Program::resolveFloatingStart(MonoNs now) {
  if (!floating || count_ == 0) return;
  MonoNs start = now;
  if (count_ >= 2) start = std::max(start, segmentEndNs(segments_[static_cast<size_t>(count_ - 2)]));
  segments_[static_cast<size_t>(count_ - 1)].start_ns = start;
  splice_ns = start;
  floating = false;
}

std::optional<Program::Spliced> Program::splice(const Program& base, SpliceRequest request) {
  const MonoNs now = request.now;
  const bool is_floating = request.floating;
  Segment& added = request.added;
  Spliced spliced;
  Program& next = spliced.program;
  next.id = request.new_id;
  next.base_id = base.id;
  next.epoch = base.epoch;
  next.rest_q = base.rest_q;
  int first = 0;
  // Segments whose successor has started by `now` will never be sampled again.
  while (first + 1 < base.count_ && base.segments_[static_cast<size_t>(first + 1)].start_ns <= now) {
    next.rest_q = base.segment(first).source->at(base.segment(first).source->durationS()).position;
    spliced.pruned_requests.emplace_back(base.segment(first).request_id, base.segment(first + 1).request_id);
    ++first;
  }
  for (int i = first; i < base.count_; ++i) {
    const Segment& segment = base.segments_[static_cast<size_t>(i)];
    if (!is_floating && segment.start_ns >= added.start_ns) {
      spliced.dropped_requests.push_back(segment.request_id);
      continue;
    }
    next.segments_[static_cast<size_t>(next.count_++)] = segment;
  }
  if (next.count_ >= kMaxSegments) return std::nullopt;
  next.floating = is_floating;
  next.splice_ns = is_floating ? 0 : added.start_ns;
  next.segments_[static_cast<size_t>(next.count_++)] = std::move(added);
  return spliced;
}

}  // namespace cyber::daemon
