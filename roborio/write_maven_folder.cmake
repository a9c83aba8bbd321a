# Lays out the Maven folder and the vendordeps (run by roborio/CMakeLists.txt; docs/roborio.md,
# "Installing"): PUBLISH_DIR/maven/GROUP/ARTIFACT/VERSION/ARTIFACT-VERSION{.jar,-sources.jar,
# -javadoc.jar,.pom}, and PUBLISH_DIR/CyberPlanner-{2026,2027}.json whose mavenUrls entry is the
# folder relative to the robot project ("cyber-planner/maven").
set(maven ${PUBLISH_DIR}/maven)
set(work ${PUBLISH_DIR}/work)
file(REMOVE_RECURSE ${maven} ${work})

# A pom with the artifact's dependencies ("group:artifact:version" each).
function(write_pom file group artifact artifact_version)
  set(deps "")
  foreach(dep ${ARGN})
    string(REPLACE ":" ";" parts ${dep})
    list(GET parts 0 g)
    list(GET parts 1 a)
    list(GET parts 2 v)
    string(APPEND deps "    <dependency>\n      <groupId>${g}</groupId>\n      <artifactId>${a}</artifactId>\n"
           "      <version>${v}</version>\n    </dependency>\n")
  endforeach()
  file(WRITE ${file} "<?xml version=\"1.0\" encoding=\"UTF-8\"?>
<project xmlns=\"http://maven.apache.org/POM/4.0.0\">
  <modelVersion>4.0.0</modelVersion>
  <groupId>${group}</groupId>
  <artifactId>${artifact}</artifactId>
  <version>${artifact_version}</version>
  <packaging>jar</packaging>
  <dependencies>
${deps}  </dependencies>
</project>
")
endfunction()

# artifact(ARTIFACT JAR SOURCE_ROOT PACKAGE CLASSPATH DEPENDENCIES...): jar, sources, javadoc, pom.
function(artifact name jar source_root package classpath)
  set(dir ${maven}/org/cyberplanner/${name}/${VERSION})
  set(base ${dir}/${name}-${VERSION})
  file(MAKE_DIRECTORY ${dir} ${work}/${name})
  file(COPY_FILE ${jar} ${base}.jar)
  execute_process(COMMAND ${JAR} cf ${base}-sources.jar -C ${source_root} . COMMAND_ERROR_IS_FATAL ANY)
  execute_process(COMMAND ${JAVADOC} -quiet -Xdoclint:none -notimestamp --release 17 -d ${work}/${name}
                          -sourcepath ${source_root} -subpackages ${package} -classpath ${classpath}
                  OUTPUT_QUIET COMMAND_ERROR_IS_FATAL ANY)
  execute_process(COMMAND ${JAR} cf ${base}-javadoc.jar -C ${work}/${name} . COMMAND_ERROR_IS_FATAL ANY)
  write_pom(${base}.pom org.cyberplanner ${name} ${VERSION} ${ARGN})
endfunction()

# Debian's LCM 1.3.1 jar ships no sources: jar and pom only.
file(MAKE_DIRECTORY ${maven}/lcm/lcm/1.3.1)
file(COPY_FILE ${LCM_JAR} ${maven}/lcm/lcm/1.3.1/lcm-1.3.1.jar)
write_pom(${maven}/lcm/lcm/1.3.1/lcm-1.3.1.pom lcm lcm 1.3.1)

set(core org.cyberplanner:cyber-planner-core:${VERSION})
artifact(cyber-lcmtypes ${LCMTYPES_JAR} ${LCMTYPES_SOURCES} cyberplanner ${LCM_JAR} lcm:lcm:1.3.1)
# The layers' sources are the ones roborio/CMakeLists.txt wrote for each year from src/wpilib.
artifact(cyber-planner-wpilib2026 ${WPILIB2026_JAR} ${WPILIB2026_SOURCES} cyberplanner.roborio.wpilib2026
         "${CORE_JAR}:${STANDINS2026_JAR}:${LCMTYPES_JAR}:${LCM_JAR}" ${core})
artifact(cyber-planner-wpilib2027 ${WPILIB2027_JAR} ${WPILIB2027_SOURCES} cyberplanner.roborio.wpilib2027
         "${CORE_JAR}:${STANDINS2027_JAR}:${LCMTYPES_JAR}:${LCM_JAR}" ${core})

# The vendordeps: one per WPILib year, the same Maven folder (write_vendordep.cmake; the 2027
# one's wpilibYear is CYBER_WPILIB_YEAR_2027, which roborio/CMakeLists.txt passes).
function(vendordep year)
  set(YEAR ${year})
  include(${SOURCE_DIR}/write_vendordep.cmake)
endfunction()
vendordep(2026)
vendordep(2027)

# Last: the core's pom is the build's output file.
artifact(cyber-planner-core ${CORE_JAR} ${SOURCE_DIR}/src/main/java cyberplanner.roborio "${LCMTYPES_JAR}:${LCM_JAR}"
         org.cyberplanner:cyber-lcmtypes:${VERSION} lcm:lcm:1.3.1)
file(REMOVE_RECURSE ${work})
