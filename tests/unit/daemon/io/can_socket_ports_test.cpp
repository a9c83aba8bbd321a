#include "cyber/daemon/io/can_socket_ports.hpp"

#include <gtest/gtest.h>

#include "cyber/can/frc_id.hpp"
#include "cyber/can/robot_frames.hpp"
#include "cyber/can/setpoint_codec.hpp"

namespace cyber::daemon::io {
namespace {

// Whether a socket with these options would hand the frame to the daemon.
bool passes(const can::SocketOptions& options, const can::Frame& frame) {
  if (!options.filters) return true;
  for (const can::IdFilter& filter : *options.filters) {
    if (can::kernelFilterMatches(can::toKernelFilter(filter), frame)) return true;
  }
  return false;
}

TEST(CanSocketPorts, TheStreamersSocketPassesOnlyTheFramesThatGateMotion) {
  const can::SocketOptions options = robotLinkSocketOptions();
  EXPECT_FALSE(options.receive_bus_errors);
  ASSERT_TRUE(options.filters.has_value());
  EXPECT_TRUE(passes(options, can::encodeHeartbeat(can::Heartbeat{})));
  EXPECT_TRUE(passes(options, can::makeBroadcastDisable()));
  can::Frame standard_zero;
  EXPECT_TRUE(passes(options, standard_zero));
  EXPECT_FALSE(passes(options, can::encodeSetpoint(1, can::Setpoint{}).value()));
  can::Frame near_heartbeat = can::encodeHeartbeat(can::Heartbeat{});
  near_heartbeat.id ^= 1;
  EXPECT_FALSE(passes(options, near_heartbeat));
  can::Frame standard_heartbeat_bits;
  standard_heartbeat_bits.id = can::kHeartbeatId & can::kStandardIdMask;
  EXPECT_FALSE(passes(options, standard_heartbeat_bits));
  can::Frame remote_disable = can::makeBroadcastDisable();
  remote_disable.remote = true;
  EXPECT_FALSE(passes(options, remote_disable));
}

TEST(CanSocketPorts, TheEventLoopsSocketReadsErrorFramesAndNoDataFrames) {
  const can::SocketOptions options = eventLoopSocketOptions();
  EXPECT_TRUE(options.receive_bus_errors);
  EXPECT_FALSE(passes(options, can::encodeHeartbeat(can::Heartbeat{})));
  EXPECT_FALSE(passes(options, can::makeBroadcastDisable()));
}

TEST(CanSocketPorts, TheGenericSocketReceivesEveryDataFrameUnlessToldOtherwise) {
  EXPECT_FALSE(can::SocketOptions{}.filters.has_value());
}

}  // namespace
}  // namespace cyber::daemon::io
