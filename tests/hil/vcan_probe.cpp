// vcan_probe IFACE: proves that one of our dynamically linked C++ binaries can use AF_CAN where
// the HIL tests run. It sends one extended frame (id 0x1F334455, 8 bytes) on a raw socket and
// reads it back on a second raw socket bound to the same interface (the kernel loops frames back
// to other local sockets), then prints "vcan_probe: ok". Exit status 1 with the failing call and
// errno text on any error, 2 on bad usage.
#include <linux/can.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/socket.h>
#include <poll.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

namespace {

constexpr canid_t kProbeId = 0x1F334455U;
constexpr std::array<unsigned char, CAN_MAX_DLEN> kProbePayload{0xCA, 0xFE, 0x00, 0x01, 0x02, 0x03, 0x04, 0x05};
constexpr int kReadTimeoutMs = 2000;

class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd_ >= 0) close(fd_);
  }
  [[nodiscard]] int get() const { return fd_; }

 private:
  int fd_;
};

int fail(const std::string& what) {
  std::fprintf(stderr, "vcan_probe: %s: %s\n", what.c_str(), std::strerror(errno));
  return 1;
}

bool bindRaw(const Fd& sock, unsigned ifindex) {
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = static_cast<int>(ifindex);
  return bind(sock.get(), reinterpret_cast<const sockaddr*>(&addr), sizeof addr) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: vcan_probe IFACE\n");
    return 2;
  }
  const std::string iface = argv[1];
  const unsigned ifindex = if_nametoindex(iface.c_str());
  if (ifindex == 0) return fail("if_nametoindex(" + iface + ")");

  const Fd tx(socket(PF_CAN, SOCK_RAW, CAN_RAW));
  const Fd rx(socket(PF_CAN, SOCK_RAW, CAN_RAW));
  if (tx.get() < 0 || rx.get() < 0) return fail("socket(PF_CAN, SOCK_RAW, CAN_RAW)");
  const can_filter only_probe{kProbeId | CAN_EFF_FLAG, CAN_EFF_MASK | CAN_EFF_FLAG | CAN_RTR_FLAG};
  if (setsockopt(rx.get(), SOL_CAN_RAW, CAN_RAW_FILTER, &only_probe, sizeof only_probe) != 0) {
    return fail("setsockopt(CAN_RAW_FILTER)");
  }
  if (!bindRaw(tx, ifindex) || !bindRaw(rx, ifindex)) return fail("bind(" + iface + ")");

  can_frame sent{};
  sent.can_id = kProbeId | CAN_EFF_FLAG;
  sent.len = CAN_MAX_DLEN;
  std::memcpy(sent.data, kProbePayload.data(), kProbePayload.size());
  if (write(tx.get(), &sent, sizeof sent) != static_cast<ssize_t>(sizeof sent)) return fail("write");

  pollfd ready{rx.get(), POLLIN, 0};
  const int polled = poll(&ready, 1, kReadTimeoutMs);
  if (polled < 0) return fail("poll");
  if (polled == 0) {
    std::fprintf(stderr, "vcan_probe: the frame did not come back within %d ms\n", kReadTimeoutMs);
    return 1;
  }
  can_frame got{};
  if (read(rx.get(), &got, sizeof got) != static_cast<ssize_t>(sizeof got)) return fail("read");
  if (got.can_id != sent.can_id || got.len != sent.len || std::memcmp(got.data, sent.data, CAN_MAX_DLEN) != 0) {
    std::fprintf(stderr, "vcan_probe: read back a different frame (id %08X len %u)\n", got.can_id, got.len);
    return 1;
  }
  std::printf("vcan_probe: ok (%s, id %08X)\n", iface.c_str(), kProbeId);
  return 0;
}
