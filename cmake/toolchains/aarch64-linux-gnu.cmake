# Cross build for arm64 coprocessors (Orange Pi 5, Raspberry Pi 4/5) with Debian 12's multiarch
# packages: `tools/setup --arch arm64` installs what this needs and `tools/package --arch arm64`
# uses it (docs/operations.md, "arm64 coprocessors").
#
# Libraries come from the :arm64 -dev packages in /usr/lib/aarch64-linux-gnu. LCM is the
# exception: Debian's liblcm1 is not Multi-Arch "same", so liblcm1:arm64 cannot be installed
# next to the amd64 one the native build and lcm-gen need. tools/setup unpacks liblcm1:arm64 and
# liblcm-dev:arm64 (with liblcm1's control files, for dpkg-shlibdeps) into CYBER_CROSS_OVERLAY.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
# No fused multiply-add contraction: g++ contracts a*b+c into one FMA instruction on AArch64
# (x86-64's baseline has none), which changed the planned durations of the public moves by up to
# 2e-3 relative (tests/arm64/public_moves.py). Without it the arm64 build plans as the amd64 one.
set(CMAKE_CXX_FLAGS_INIT -ffp-contract=off)

# The overlay tools/setup --arch arm64 writes (tools/arm64-run reads it too).
set(CYBER_CROSS_OVERLAY /opt/cyber-planner-cross/arm64)
if(NOT EXISTS ${CYBER_CROSS_OVERLAY}/usr/lib/aarch64-linux-gnu/liblcm.so)
  message(FATAL_ERROR "no arm64 LCM in ${CYBER_CROSS_OVERLAY}: run tools/setup --arch arm64")
endif()
# The Debian package's dependencies: dpkg-shlibdeps finds liblcm.so.1 there, and liblcm1's
# shlibs file in the overlay's DEBIAN/ (cmake/Packaging.cmake).
set(CYBER_CROSS_PRIVATE_LIB_DIRS ${CYBER_CROSS_OVERLAY}/usr/lib/aarch64-linux-gnu)
set(CYBER_DEB_ARCHITECTURE arm64)

# Host programs (lcm-gen, java) from the host; headers and libraries from the multiarch
# directories (root /) and the overlay.
set(CMAKE_FIND_ROOT_PATH / ${CYBER_CROSS_OVERLAY})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
# pkg-config for the arm64 .pc files (Debian's wrapper sets PKG_CONFIG_LIBDIR for the triplet),
# with the overlay's lcm.pc after them.
set(PKG_CONFIG_EXECUTABLE aarch64-linux-gnu-pkg-config CACHE FILEPATH "pkg-config for arm64")
set(ENV{PKG_CONFIG_PATH} ${CYBER_CROSS_OVERLAY}/usr/lib/aarch64-linux-gnu/pkgconfig)

# Tests and gtest discovery run the arm64 programs under QEMU's user-mode emulator, started
# explicitly by tools/arm64-run: binfmt_misc is often not mounted in containers and on CI machines.
set(CMAKE_CROSSCOMPILING_EMULATOR ${CMAKE_CURRENT_LIST_DIR}/../../tools/arm64-run)
