# Install-time part of cmake/Packaging.cmake: the systemd unit and the configuration, whose
# paths follow the install prefix. The shipped unit names /usr/bin and /etc/cyber-planner (the
# package's paths); for any other prefix P they become P/bin and P/etc/cyber-planner.
if(CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  set(etc_dir /etc)
else()
  set(etc_dir ${CMAKE_INSTALL_PREFIX}/etc)
endif()

file(READ ${cyber_source_dir}/systemd/cyber-planner.service unit)
if(NOT CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  string(REPLACE "/usr/bin/" "${CMAKE_INSTALL_PREFIX}/bin/" unit "${unit}")
  string(REPLACE "/usr/share/" "${CMAKE_INSTALL_PREFIX}/share/" unit "${unit}")
  string(REPLACE "/etc/cyber-planner/" "${etc_dir}/cyber-planner/" unit "${unit}")
endif()
file(WRITE ${cyber_binary_dir}/install/cyber-planner.service "${unit}")
file(INSTALL DESTINATION ${CMAKE_INSTALL_PREFIX}/lib/systemd/system TYPE FILE
     FILES ${cyber_binary_dir}/install/cyber-planner.service)

# The robot configuration: the reference robot with an LCM URL whose packets leave the coprocessor
# (ttl=1: the robot LAN, where the roboRIO is; docs/roborio.md). The source tree's copy keeps
# ttl=0, so tests and a developer's desktop stay on their host. Never overwrite one that is there
# (the package's copy is a conffile, which dpkg handles itself; its staging root is always fresh).
file(READ ${cyber_source_dir}/config/reefscape-2025.toml robot_toml)
set(host_url [[lcm_url = "udpm://239.255.76.67:5810?ttl=0"]])
set(lan_url [[lcm_url = "udpm://239.255.76.67:5810?ttl=1"]])
string(FIND "${robot_toml}" "${host_url}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "config/reefscape-2025.toml has no line '${host_url}' to turn into ttl=1")
endif()
string(REPLACE "${host_url}" "${lan_url}" robot_toml "${robot_toml}")
file(WRITE ${cyber_binary_dir}/install/robot.toml "${robot_toml}")
set(config $ENV{DESTDIR}${etc_dir}/cyber-planner/robot.toml)
if(EXISTS ${config})
  message(STATUS "Keeping: ${config} (the default is share/cyber-planner/reefscape-2025.toml)")
else()
  file(INSTALL DESTINATION ${etc_dir}/cyber-planner TYPE FILE FILES ${cyber_binary_dir}/install/robot.toml)
endif()
