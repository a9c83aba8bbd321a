# Warnings for the project's own targets (not for generated code). They are errors only where the
# project's own checks ask for it (CYBER_WERROR: tools/test and CI turn it on): a newer compiler's
# new warning must not stop a team's plain build for its coprocessor.
function(cyber_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(CYBER_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# One library per component: sources in src/, public headers in include/.
function(cyber_component_library target)
  cmake_parse_arguments(ARG "" "" "LINK" ${ARGN})
  file(GLOB_RECURSE srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp)
  add_library(${target} STATIC ${srcs})
  target_include_directories(${target} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(${target} PUBLIC ${ARG_LINK})
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  cyber_warnings(${target})
endfunction()

# Every *_test.cpp in DIR (RECURSE: and in its subfolders) becomes its own GoogleTest executable,
# so one broken file cannot stop the others from building; tests carry LABEL.
# CYBER_SWEEP_TEST_FILTER, when set (the cross and the sanitizer builds, tests/CMakeLists.txt), is
# a GoogleTest filter of the tests registered.
function(cyber_test_dir dir label)
  cmake_parse_arguments(ARG "RECURSE" "" "LINK" ${ARGN})
  set(filter)
  if(DEFINED CYBER_SWEEP_TEST_FILTER)
    set(filter TEST_FILTER ${CYBER_SWEEP_TEST_FILTER})
  endif()
  if(ARG_RECURSE)
    file(GLOB_RECURSE srcs CONFIGURE_DEPENDS ${dir}/*_test.cpp)
  else()
    file(GLOB srcs CONFIGURE_DEPENDS ${dir}/*_test.cpp)
  endif()
  foreach(src ${srcs})
    get_filename_component(name ${src} NAME_WE)
    add_executable(${name} ${src})
    target_link_libraries(${name} PRIVATE ${ARG_LINK} GTest::gtest_main)
    target_include_directories(${name} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/support)
    cyber_warnings(${name})
    gtest_discover_tests(${name} PROPERTIES LABELS ${label} DISCOVERY_TIMEOUT 60 ${filter})
  endforeach()
endfunction()

# A tool's command line (its *_arguments.cpp, parsed with cli/) as a library of its own, so that
# the tool's unit tests link it without the tool's main().
function(cyber_tool_arguments target)
  cmake_parse_arguments(ARG "" "" "SOURCES;LINK" ${ARGN})
  add_library(${target} STATIC ${ARG_SOURCES})
  target_include_directories(${target} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR})
  target_link_libraries(${target} PUBLIC cyber_cli ${ARG_LINK})
  cyber_warnings(${target})
endfunction()
