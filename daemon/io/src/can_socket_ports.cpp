#include "cyber/daemon/io/can_socket_ports.hpp"

#include "cyber/can/frc_id.hpp"

namespace cyber::daemon::io {

std::vector<can::IdFilter> robotLinkFilters() {
  return {can::IdFilter::exact(can::kHeartbeatId, true), can::IdFilter::exact(can::kBroadcastDisableId, true),
          can::IdFilter::exact(can::kBroadcastDisableId, false)};
}

can::SocketOptions robotLinkSocketOptions() {
  can::SocketOptions options;
  options.filters = robotLinkFilters();
  options.receive_bus_errors = false;
  return options;
}

can::SocketOptions eventLoopSocketOptions() {
  can::SocketOptions options;
  options.filters = std::vector<can::IdFilter>{};
  options.receive_bus_errors = true;
  return options;
}

}  // namespace cyber::daemon::io
