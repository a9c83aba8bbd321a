#include <gtest/gtest.h>

#include <sys/socket.h>
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>

#include "cyber/can/can_socket.hpp"
#include "cyber/can/frc_id.hpp"
#include "cyber/can/robot_frames.hpp"
#include "cyber/can/setpoint_codec.hpp"

namespace cyber::can {
namespace {

bool kernelHasCan() {
  const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) return false;
  ::close(fd);
  return true;
}

bool fdIsOpen(int fd) { return ::fcntl(fd, F_GETFD) != -1 || errno != EBADF; }

TEST(CanSocket, OpenFailsCleanlyWithoutCanOrInterface) {
  const auto socket = CanSocket::open("cybervcan9");  // never created by anything
  ASSERT_FALSE(socket.ok());
  EXPECT_NE(socket.error().message.find("cybervcan9"), std::string::npos) << socket.error().message;
  if (kernelHasCan()) {
    EXPECT_EQ(socket.status(), OpenError::kNoSuchInterface);
  } else {
    EXPECT_EQ(socket.status(), OpenError::kKernelWithoutCan);
    // The errno of socket(PF_CAN) is in the message.
    // Built with append: g++ 12 at -O3 warns falsely (-Wrestrict) on "literal" + std::string&&.
    std::string in_parentheses = "(";
    in_parentheses.append(errnoText(EAFNOSUPPORT)).append(")");
    EXPECT_NE(socket.error().message.find(in_parentheses), std::string::npos) << socket.error().message;
    EXPECT_NE(socket.error().message.find("address family not supported"), std::string::npos) << socket.error().message;
    EXPECT_NE(socket.error().message.find("kernel without CAN"), std::string::npos);
  }
}

TEST(CanSocket, OpenOnVcan0EitherWorksOrSaysWhy) {
  const auto socket = CanSocket::open("vcan0");
  if (socket.ok()) {
    EXPECT_GE(socket.value().fd(), 0);
  } else {
    EXPECT_FALSE(socket.error().message.empty());
    EXPECT_NE(socket.status(), OpenError::kInvalidName);
  }
}

TEST(CanSocket, RejectsInvalidNamesBeforeAnySystemCall) {
  for (const char* name : {"", "a/b", "has space", "sixteen-chars-xx"}) {
    const auto socket = CanSocket::open(name);
    ASSERT_FALSE(socket.ok()) << name;
    EXPECT_EQ(socket.status(), OpenError::kInvalidName) << name;
    // No system call ran, so no errno text follows the cause.
    EXPECT_EQ(socket.error().message, "CAN interface '" + std::string(name) +
                                          "': invalid interface name (1 to 15 characters, no '/' or white space)");
  }
  EXPECT_NE(CanSocket::open("fifteen-chars-x").status(), OpenError::kInvalidName);
}

// A SOCK_SEQPACKET pair keeps message boundaries like a CAN raw socket, so the read/write paths
// run for real on a kernel without CAN.
struct SocketPair {
  SocketPair() {
    int fds[2];
    EXPECT_EQ(::socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_NONBLOCK | SOCK_CLOEXEC, 0, fds), 0);
    a = fds[0];
    b = fds[1];
  }
  int a = -1;
  int b = -1;
};

TEST(CanSocket, WritesAndReadsWholeFrames) {
  SocketPair pair;
  CanSocket sender = CanSocket::adopt(pair.a);
  CanSocket receiver = CanSocket::adopt(pair.b);

  Frame frame;
  EXPECT_EQ(receiver.read(frame).status, IoStatus::kWouldBlock);

  const Frame setpoint = encodeSetpoint(1, Setpoint{0.5, -0.25, 1.5, 9}).value();
  const Frame heartbeat = encodeHeartbeat(Heartbeat{false, true, false, false, true});
  Frame error;
  error.error = true;
  error.id = 0x40;
  error.dlc = 8;
  ASSERT_TRUE(sender.write(setpoint).ok());
  ASSERT_TRUE(sender.write(heartbeat).ok());
  ASSERT_TRUE(sender.write(error).ok());
  ASSERT_TRUE(receiver.read(frame).ok());
  EXPECT_EQ(frame, setpoint);
  ASSERT_TRUE(receiver.read(frame).ok());
  EXPECT_EQ(frame, heartbeat);
  ASSERT_TRUE(receiver.read(frame).ok());
  EXPECT_EQ(frame, error);
  const IoResult empty = receiver.read(frame);
  EXPECT_EQ(empty.status, IoStatus::kWouldBlock);
  EXPECT_EQ(empty.error_number, EAGAIN);
}

TEST(CanSocket, ShortMessageIsAnError) {
  SocketPair pair;
  CanSocket receiver = CanSocket::adopt(pair.b);
  const char five[5] = {1, 2, 3, 4, 5};
  ASSERT_EQ(::write(pair.a, five, sizeof five), 5);
  Frame frame;
  const IoResult result = receiver.read(frame);
  EXPECT_EQ(result.status, IoStatus::kError);
  EXPECT_EQ(result.error_number, EMSGSIZE);
  EXPECT_FALSE(result.message().empty());
  ::close(pair.a);
}

TEST(CanSocket, WriteToClosedPeerIsATypedError) {
  auto* previous = std::signal(SIGPIPE, SIG_IGN);
  SocketPair pair;
  CanSocket sender = CanSocket::adopt(pair.a);
  ::close(pair.b);
  const IoResult result = sender.write(makeBroadcastDisable());
  EXPECT_EQ(result.status, IoStatus::kError);
  EXPECT_EQ(result.error_number, EPIPE);
  EXPECT_NE(result.message().find("pipe"), std::string::npos) << result.message();
  std::signal(SIGPIPE, previous);
}

TEST(CanSocket, OwnsItsDescriptor) {
  SocketPair pair;
  {
    CanSocket first = CanSocket::adopt(pair.a);
    CanSocket second = std::move(first);
    EXPECT_EQ(first.fd(), -1);  // NOLINT(bugprone-use-after-move): checking the moved-from state
    EXPECT_EQ(second.fd(), pair.a);
    CanSocket third = CanSocket::adopt(pair.b);
    third = std::move(second);  // closes pair.b
    EXPECT_FALSE(fdIsOpen(pair.b));
    EXPECT_TRUE(fdIsOpen(pair.a));
  }
  EXPECT_FALSE(fdIsOpen(pair.a));
}

TEST(IoResult, ErrnoMapping) {
  EXPECT_EQ(ioResultFromErrno(EAGAIN).status, IoStatus::kWouldBlock);
  EXPECT_EQ(ioResultFromErrno(ENOBUFS).status, IoStatus::kNoBufferSpace);
  EXPECT_EQ(ioResultFromErrno(ENETDOWN).status, IoStatus::kNetworkDown);
  EXPECT_EQ(ioResultFromErrno(EIO).status, IoStatus::kError);
  EXPECT_EQ(ioResultFromErrno(EIO).error_number, EIO);
  EXPECT_NE(ioResultFromErrno(ENOBUFS).message().find("no buffer space"), std::string::npos);
  EXPECT_NE(ioResultFromErrno(ENETDOWN).message().find("network down"), std::string::npos);
  EXPECT_EQ(IoResult{}.message(), "ok");
}

TEST(IdFilter, MaskSelectsAllDevicesOfOneApi) {
  // Setpoints from any device: everything but the 6 device bits must match.
  const IdFilter all_setpoints{teamFrameId(kSetpointApiClass, kSetpointApiIndex, 0), kExtendedIdMask & ~0x3Fu, true};
  const can_filter kernel = toKernelFilter(all_setpoints);
  for (std::uint8_t device = 0; device <= kMaxDeviceNumber; ++device) {
    EXPECT_TRUE(kernelFilterMatches(kernel, encodeSetpoint(device, Setpoint{}).value()));
  }
  Frame status;
  status.extended = true;
  status.id = teamFrameId(kStatusApiClass, kStatusApiIndex, 1);
  EXPECT_FALSE(kernelFilterMatches(kernel, status));
}

}  // namespace
}  // namespace cyber::can
