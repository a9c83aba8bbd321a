#include "own_udp_sockets.hpp"

#include <sys/socket.h>
#include <dirent.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace cyber::test {

namespace {

// inode -> drops, for every UDP socket of the namespace (IPv4; LCM's udpm provider is IPv4 only).
std::map<std::uint64_t, std::int64_t> udpTable() {
  std::map<std::uint64_t, std::int64_t> table;
  std::ifstream file("/proc/self/net/udp");
  std::string line;
  std::getline(file, line);  // header
  while (std::getline(file, line)) {
    // sl local rem st tx:rx tr:when retrnsmt uid timeout inode ref pointer drops
    std::istringstream fields(line);
    std::string field[13];
    int n = 0;
    while (n < 13 && fields >> field[n]) ++n;
    if (n < 13) continue;
    table[std::strtoull(field[9].c_str(), nullptr, 10)] = std::strtoll(field[12].c_str(), nullptr, 10);
  }
  return table;
}

}  // namespace

std::vector<OwnUdpSocket> ownUdpSockets() {
  const auto table = udpTable();
  std::vector<OwnUdpSocket> out;
  DIR* dir = opendir("/proc/self/fd");
  if (dir == nullptr) return out;
  const std::string prefix = "socket:[";
  while (const dirent* entry = readdir(dir)) {
    const std::string name = entry->d_name;
    if (name == "." || name == "..") continue;
    char target[64] = {};
    const ssize_t length = readlink(("/proc/self/fd/" + name).c_str(), target, sizeof(target) - 1);
    if (length <= 0) continue;
    const std::string link(target, static_cast<size_t>(length));
    if (link.rfind(prefix, 0) != 0) continue;
    const std::uint64_t inode = std::strtoull(link.c_str() + prefix.size(), nullptr, 10);
    if (table.count(inode) != 0) out.push_back(OwnUdpSocket{std::atoi(name.c_str()), inode});
  }
  closedir(dir);
  return out;
}

std::int64_t kernelDrops(const std::vector<OwnUdpSocket>& sockets) {
  const auto table = udpTable();
  std::int64_t drops = 0;
  for (const auto& socket : sockets) {
    if (auto it = table.find(socket.inode); it != table.end()) drops += it->second;
  }
  return drops;
}

long long forceReceiveBuffer(const std::vector<OwnUdpSocket>& sockets, int bytes) {
  long long smallest = -1;
  for (const auto& socket : sockets) {
    if (setsockopt(socket.fd, SOL_SOCKET, SO_RCVBUFFORCE, &bytes, sizeof(bytes)) != 0) return -1;
    int got = 0;
    socklen_t size = sizeof(got);
    if (getsockopt(socket.fd, SOL_SOCKET, SO_RCVBUF, &got, &size) != 0) return -1;
    smallest = smallest < 0 ? got : std::min<long long>(smallest, got);
  }
  return smallest;
}

}  // namespace cyber::test
