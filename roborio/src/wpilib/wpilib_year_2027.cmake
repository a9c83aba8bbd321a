# The "wpilibYear" of the 2027 vendordep when the build names none (docs/roborio.md, "Installing").
# GradleRIO's 2027 line refuses a vendordep whose wpilibYear is not exactly its own: its
# WPIExtension hands its wpilibYear to native-utils' WPIVendorDepsExtension, whose
# validateDependencies throws InvalidVendorDepYearException on any other value. GradleRIO's main
# branch (commit 7b93a1301dad876e64143485c296eec407eab2cc, 2026-08-16) and its releases
# v2027.0.0-alpha-5 and -alpha-6 set wpilibYear.convention("2027_alpha5"). A robot project on
# another 2027 pre-release builds with -DCYBER_WPILIB_YEAR_2027=ITS_YEAR (roborio/CMakeLists.txt).
set(CYBER_WPILIB_YEAR_2027_DEFAULT 2027_alpha5)
