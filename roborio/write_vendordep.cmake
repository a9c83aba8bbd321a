# Writes one WPILib year's vendordep, PUBLISH_DIR/CyberPlanner-YEAR.json, from vendordep.json.in
# (run by write_maven_folder.cmake for 2026 and 2027, and by tests/system/roborio_vendordep.sh):
#   cmake -DSOURCE_DIR=roborio -DPUBLISH_DIR=DIR -DVERSION=V -DYEAR=2026|2027
#         [-DCYBER_WPILIB_YEAR_2027=2027_alphaN] -P write_vendordep.cmake
# Its year key and value, and the command-based vendordep it requires, come from
# src/wpilib/years.cmake; its mavenUrls entry is the Maven folder relative to the robot project.
foreach(name SOURCE_DIR PUBLISH_DIR VERSION YEAR)
  if(NOT DEFINED ${name})
    message(FATAL_ERROR "write_vendordep.cmake needs -D${name}=...")
  endif()
endforeach()
set(MAVEN_URL cyber-planner/maven)
include(${SOURCE_DIR}/src/wpilib/years.cmake)
configure_file(${SOURCE_DIR}/vendordep.json.in ${PUBLISH_DIR}/CyberPlanner-${YEAR}.json @ONLY)
