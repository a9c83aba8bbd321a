// The streaming path must not allocate: global operator new is counted while the streamer ticks
// and the frame writer writes, through holding, adopting, moving, splicing, stopping and faults.

// The replaced operator new/delete below pair malloc with free; g++ cannot see that through the
// replacement and warns at inlined call sites.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <limits>
#include <new>

#include "cyber/can/robot_frames.hpp"
#include "cyber/daemon/frame_writer.hpp"
#include "cyber/daemon/robot_link.hpp"
#include "cyber/daemon/streamer.hpp"
#include "fake_trajectory.hpp"
#include "reference_model.hpp"
#include "splice_into.hpp"

namespace {
std::atomic<long> g_allocations{0};
std::atomic<bool> g_counting{false};
}  // namespace

// Replaced as a pair (also under AddressSanitizer, which checks that they match).
void* operator new(std::size_t size) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace cyber::daemon {
namespace {

constexpr MonoNs kMs = 1'000'000;

struct NullPort final : CanPort {
  bool fail = false;
  can::IoResult write(const can::Frame&) override { return fail ? can::ioResultFromErrno(ENOBUFS) : can::IoResult{}; }
};

// While live, a heartbeat and a malformed one per tick, then EAGAIN; otherwise ENETDOWN.
struct BusSource final : RobotFrameSource {
  bool live = true;
  int step = 0;
  can::IoResult read(can::Frame& frame) override {
    if (!live) return can::ioResultFromErrno(ENETDOWN);
    can::Heartbeat enabled;
    enabled.system_watchdog = true;
    switch (step++ % 3) {
      case 0: frame = can::encodeHeartbeat(enabled); return {};
      case 1:
        frame = can::encodeHeartbeat(enabled);
        frame.dlc = 3;
        return {};
      default: return can::ioResultFromErrno(EAGAIN);
    }
  }
};

TEST(StreamerAllocation, TicksAndFrameWritesNeverAllocate) {
  const auto& robot = cyber::test::referenceModel();
  StreamerSettings settings;
  settings.gate.require_robot_enabled = true;
  Streamer streamer(HoldModel(robot), settings);
  NullPort port;
  FrameWriter writer(port, FrameWriterSettings{{1, 2}, 3, 20});
  BusSource bus;
  RobotLink link;
  RobotInputs inputs;
  MonoNs now = 1000 * kMs;
  const JointVector a{{0.2, 1.57}}, b{{1.5, 3.0}}, c{{0.6, 2.9}};

  // Programs are built outside the counted region, as the event loop does.
  std::vector<std::int64_t> dropped;
  dropped.reserve(16);
  auto* first = new Program();
  auto* splice = new Program();
  auto* faulty = new Program();
  long allocations = 0;
  auto run = [&](int ticks, Program* offered, bool enabled, bool fail_writes) {
    port.fail = fail_writes;
    for (int i = 0; i < ticks; ++i) {
      inputs.state_ns = now;
      inputs.measured_q = a;
      if (enabled) {
        inputs.heartbeat_ns = now;
        inputs.heartbeat_watchdog = true;
      }
      TickOutput out;
      bus.live = enabled;
      g_counting = true;
      RobotInputs merged = inputs;  // as the streamer thread does: its own reading of the bus first
      drainRobotFrames(bus, now, link);
      applyRobotLink(link, merged);
      streamer.tick(now, merged, i == 0 ? offered : nullptr, false, out);
      writer.write(out, 0);
      g_counting = false;
      allocations += g_allocations.exchange(0);
      for (int k = 0; k < out.retired_count; ++k) delete out.retired[static_cast<size_t>(k)];
      now += 5 * kMs;
    }
  };

  run(10, nullptr, true, false);  // enable, hold
  ASSERT_TRUE(test::spliceInto(Program::holdAt(streamer.epoch(), a),
                               {now, Segment{test::makeHermite(a, JointVector::Zero(2), b, 1.0, robot), 1, 0}, true, 1},
                               *first, dropped));
  run(40, first, true, false);  // adopt and move
  const MonoNs branch = now + 30 * kMs;
  Program copy = *first;
  const ProgramSample at = copy.sample(branch, HoldModel(robot));
  ASSERT_TRUE(test::spliceInto(
      copy,
      {now, Segment{test::makeHermite(at.setpoints.position, at.setpoints.velocity, c, 1.0, robot), 2, branch}, false,
       2},
      *splice, dropped));
  run(300, splice, true, true);    // splice and run to the end, every CAN write failing
  run(40, nullptr, false, false);  // heartbeat lost: stop
  run(10, nullptr, true, false);   // re-enabled: hold measured
  ASSERT_TRUE(test::spliceInto(
      Program::holdAt(streamer.epoch(), a),
      {now, Segment{std::make_shared<test::NanAfterTrajectory>(0.05, (JointVector{{0.2, 1.57}})), 3, 0}, true, 3},
      *faulty, dropped));
  run(40, faulty, true, false);  // fault
  EXPECT_EQ(allocations, 0);
  EXPECT_GT(writer.framesSent(), 0);
}

}  // namespace
}  // namespace cyber::daemon
