#pragma once
// What the streamer executes: a rest position followed by a short chain of trajectory segments,
// each starting at an absolute time. A new plan is spliced into a copy of the running program; the
// copy equals the running program before the splice time, so the streamer can switch to it at any
// tick before that time without a jump in position or velocity.

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "cyber/daemon/hold_model.hpp"
#include "cyber/daemon/mono_time.hpp"
#include "cyber/daemon/setpoint_source.hpp"

namespace cyber::daemon {

inline constexpr int kMaxSegments = 8;

struct Segment {
  SharedSetpointSource source;
  std::int64_t request_id = -1;
  MonoNs start_ns = 0;
};

// What a splice adds to its base program.
struct SpliceRequest {
  MonoNs now = 0;         // segments that can no longer be sampled at or after now are pruned
  Segment added;          // for a floating splice added.start_ns is ignored (set on adoption)
  bool floating = false;  // start when adopted, after the running segments end
  std::uint64_t new_id = 0;
};

struct ProgramSample {
  JointSetpoints setpoints;
  int segment = -1;              // index of the segment in effect, -1 before the first
  std::int64_t request_id = -1;  // its request, -1 when resting at rest_q
  double segment_time_s = 0.0;   // time into that segment (clamped to its duration)
  bool moving = false;           // inside a segment (false once it has finished: holding its end)
  bool last_segment = false;     // the segment in effect is the program's last one
};

class Program {
 public:
  // A program with no segments: hold q. Id 0 marks the streamer's own hold programs.
  static Program holdAt(std::uint64_t epoch, const JointVector& q);

  std::uint64_t id = 0;       // unique per posted program; 0 for the streamer's own
  std::uint64_t base_id = 0;  // the program this one was spliced into
  std::uint64_t epoch = 0;    // streamer epoch it is valid for (bumped on every stop/re-enable)
  JointVector rest_q;         // position before the first segment

  // The last segment starts at splice_ns (fixed splice), or, when floating, when the streamer
  // adopts the program but not before the previous segments end (start from rest).
  MonoNs splice_ns = 0;
  bool floating = false;

  [[nodiscard]] int segmentCount() const { return count_; }
  [[nodiscard]] const Segment& segment(int i) const { return segments_[static_cast<size_t>(i)]; }
  [[nodiscard]] bool full() const { return count_ == kMaxSegments; }

  // End of the last segment; kNever without segments.
  [[nodiscard]] MonoNs endNs() const;
  // Where the program comes to rest: the end of its last segment, or rest_q.
  [[nodiscard]] JointVector restPosition() const;
  [[nodiscard]] ProgramSample sample(MonoNs t, const HoldModel& hold) const;

  // Resolves a floating start at adoption time `now`: the last segment starts at
  // max(now, end of the segments before it).
  void resolveFloatingStart(MonoNs now);

  // Drops every segment (the streamer's own hold programs reuse one object without allocating).
  void resetToHold(std::uint64_t epoch_value, const JointVector& q);

  struct Spliced;
  // Builds the successor of `base`: the same motion up to the new segment's start, then
  // `request.added`. Segments that would start at or after the new one are dropped, segments that
  // are over are pruned (the request ids of both are in the result). Nothing when the chain is full
  // (the caller waits for segments to age out).
  static std::optional<Spliced> splice(const Program& base, SpliceRequest request);

 private:
  std::array<Segment, kMaxSegments> segments_{};
  int count_ = 0;
};

struct Program::Spliced {
  Program program;
  std::vector<std::int64_t> dropped_requests;  // requests of the segments the splice replaced
  // Requests of the segments pruned because their successor had started by `now`, each with the
  // request of that successor. A segment that started less than a stream period before its
  // successor may never have been streamed, so no streamer event ever names it.
  std::vector<std::pair<std::int64_t, std::int64_t>> pruned_requests;
};

}  // namespace cyber::daemon
