#pragma once
// What the kernel did with this process's own UDP sockets: which they are (the socket links in
// /proc/self/fd), how many datagrams the kernel dropped on them (the `drops` column of
// /proc/self/net/udp, which lists every UDP socket of the network namespace), and forcing their
// receive buffer past net.core.rmem_max (SO_RCVBUFFORCE, root only), so that a test does not
// depend on a sysctl a fresh machine lacks (Debian's default rmem_max is 212992).

#include <cstdint>
#include <vector>

namespace cyber::test {

struct OwnUdpSocket {
  int fd = -1;
  std::uint64_t inode = 0;
};

// Every socket among this process's file descriptors that /proc/self/net/udp lists.
std::vector<OwnUdpSocket> ownUdpSockets();

// Sum of the kernel's drop counts over `sockets`.
std::int64_t kernelDrops(const std::vector<OwnUdpSocket>& sockets);

// Sets SO_RCVBUFFORCE on each socket; returns the smallest SO_RCVBUF the kernel then reports
// (it doubles the request for its bookkeeping), or -1 if a call failed.
long long forceReceiveBuffer(const std::vector<OwnUdpSocket>& sockets, int bytes);

}  // namespace cyber::test
