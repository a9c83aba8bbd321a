# Lays out the local Maven folder the vendordep JSON points at (run by roborio/CMakeLists.txt):
# MAVEN_DIR/GROUP/ARTIFACT/VERSION/ARTIFACT-VERSION.{jar,pom}.
function(maven_artifact group_path group artifact artifact_version jar)
  set(dir ${MAVEN_DIR}/${group_path}/${artifact}/${artifact_version})
  file(MAKE_DIRECTORY ${dir})
  file(COPY_FILE ${jar} ${dir}/${artifact}-${artifact_version}.jar)
  file(WRITE ${dir}/${artifact}-${artifact_version}.pom
"<?xml version=\"1.0\" encoding=\"UTF-8\"?>
<project xmlns=\"http://maven.apache.org/POM/4.0.0\">
  <modelVersion>4.0.0</modelVersion>
  <groupId>${group}</groupId>
  <artifactId>${artifact}</artifactId>
  <version>${artifact_version}</version>
  <packaging>jar</packaging>
</project>
")
endfunction()
maven_artifact(org/cyberplanner org.cyberplanner cyber-lcmtypes ${VERSION} ${LCMTYPES_JAR})
maven_artifact(lcm lcm lcm 1.3.1 ${LCM_JAR})
# Last: its jar is the build's output file.
maven_artifact(org/cyberplanner org.cyberplanner cyber-roborio ${VERSION} ${ROBORIO_JAR})
