# Install layout and the Debian package (docs/operations.md, "Install and package").
#   cmake --install BUILD --prefix /usr     the layout below (with DESTDIR for a staging root)
#   cpack --config BUILD/CPackConfig.cmake  cyber-planner_VERSION_ARCH.deb
#
# Layout (prefix /usr, as in the package):
#   bin/cyber-plannerd, bin/cyber-can-decode      here, when they are built (cyber-plan,
#                                                 cyber-goal, cyber-plant-sim install themselves)
#   bin/cyber-lcm-spy                             tools/lcm-spy
#   share/cyber-planner/java/cyber_lcmtypes.jar   the LCM types for lcm-spy
#   lib/systemd/system/cyber-planner.service      not enabled by the package
#   share/cyber-planner/network/                  networkd files for can0 / vcan0: examples to
#                                                 copy, since installing them would reconfigure
#                                                 CAN interfaces on any machine running networkd
#   /etc/cyber-planner/robot.toml                 the default robot (a conffile; for another
#                                                 prefix P it goes to P/etc, and an existing
#                                                 file is kept)
#   share/cyber-planner/reefscape-2025.toml       the same default, untouched, for reference
#   share/doc/cyber-planner/                      README.md and docs/*.md
set(cyber_data_dir share/cyber-planner)
set(cyber_doc_dir share/doc/cyber-planner)

install(TARGETS cyber-plannerd cyber-can-decode RUNTIME DESTINATION bin)
install(PROGRAMS ${PROJECT_SOURCE_DIR}/tools/lcm-spy DESTINATION bin RENAME cyber-lcm-spy)
install(FILES ${CYBER_LCMTYPES_JAR} DESTINATION ${cyber_data_dir}/java)

file(GLOB cyber_network_files CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/systemd/network/*)
install(FILES ${cyber_network_files} DESTINATION ${cyber_data_dir}/network)
install(FILES ${PROJECT_SOURCE_DIR}/config/reefscape-2025.toml DESTINATION ${cyber_data_dir})
file(GLOB cyber_docs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/*.md)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${cyber_docs} DESTINATION ${cyber_doc_dir})

# The unit and the configuration depend on the prefix given at install time.
install(CODE "set(cyber_source_dir [[${PROJECT_SOURCE_DIR}]])\nset(cyber_binary_dir [[${PROJECT_BINARY_DIR}]])")
install(SCRIPT ${CMAKE_CURRENT_LIST_DIR}/InstallSystemFiles.cmake)

# ---- Debian package ----
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME cyber-planner)
set(CPACK_PACKAGE_VENDOR "cyber-planner")
set(CPACK_PACKAGE_CONTACT "cyber-planner developers <cyber-planner@example.invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "time-optimal motion planner daemon for an FRC elevator and arm")
set(CPACK_PACKAGE_DESCRIPTION
  "cyber-plannerd takes goals and measured state over LCM, plans collision-free, time-optimal\n"
  "motions for an elevator with an arm and streams timed setpoints to the motor controllers\n"
  "over SocketCAN. Includes the offline planner cyber-plan, CAN and LCM tools, a hardened\n"
  "systemd unit and a launcher for lcm-spy with the project's message types.")
string(REPLACE ";" "" CPACK_PACKAGE_DESCRIPTION "${CPACK_PACKAGE_DESCRIPTION}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION misc)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# Library dependencies from the binaries themselves (dpkg-shlibdeps, package dpkg-dev).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# A cross build's toolchain file names the package architecture and where dpkg-shlibdeps finds
# the libraries no installed package holds (cmake/toolchains/aarch64-linux-gnu.cmake).
if(CYBER_DEB_ARCHITECTURE)
  set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE ${CYBER_DEB_ARCHITECTURE})
endif()
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${CYBER_CROSS_PRIVATE_LIB_DIRS})
# cyber-lcm-spy needs Java and LCM's Java bindings; can-utils for candump captures.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "default-jre | java-runtime, liblcm-java, libjchart2d-java, liblcm-bin, can-utils")
set(cyber_conffiles ${PROJECT_BINARY_DIR}/cpack/conffiles)
file(WRITE ${cyber_conffiles} "/etc/cyber-planner/robot.toml\n")
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${cyber_conffiles})
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
include(CPack)
