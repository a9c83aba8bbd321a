# What WPILib 2026 (the roboRIO) and WPILib 2027 (the Systemcore) spell their own way, as the
# @NAME@s of the layer's templates (java/, test/) and of the vendordep (roborio/vendordep.json.in):
# by_year(NAME VALUE_2026 VALUE_2027). roborio/CMakeLists.txt and write_maven_folder.cmake set YEAR
# and include this file, which sets each NAME to that year's value. The classes named here have
# stand-ins in src/standins2026 and src/standins2027.
set(wpilib_years 2026 2027)
list(FIND wpilib_years "${YEAR}" wpilib_column)
if(wpilib_column LESS 0)
  message(FATAL_ERROR "src/wpilib/years.cmake has no values for WPILib '${YEAR}'")
endif()
math(EXPR wpilib_column "${wpilib_column} + 1")
# Each value is one argument (ARGV1, ARGV2), so imports may hold ';' (ARGN would split them).
function(by_year name)
  list(LENGTH wpilib_years count)
  math(EXPR expected "${count} + 1")
  if(NOT ARGC EQUAL expected)
    message(FATAL_ERROR "src/wpilib/years.cmake: ${name} needs one value per year (${wpilib_years})")
  endif()
  set(${name} "${ARGV${wpilib_column}}" PARENT_SCOPE)
endfunction()

# The vendordep: its year key and value, and WPILib's command-based vendordep it requires. The
# 2027 value is the build's CYBER_WPILIB_YEAR_2027, by default the one GradleRIO's 2027 line
# expects now (wpilib_year_2027.cmake).
if(NOT CYBER_WPILIB_YEAR_2027)
  include(${CMAKE_CURRENT_LIST_DIR}/wpilib_year_2027.cmake)
  set(CYBER_WPILIB_YEAR_2027 ${CYBER_WPILIB_YEAR_2027_DEFAULT})
endif()
if(NOT CYBER_WPILIB_YEAR_2027 MATCHES "^2027(_[a-z]+[0-9]+)?$")
  message(FATAL_ERROR "CYBER_WPILIB_YEAR_2027 = '${CYBER_WPILIB_YEAR_2027}' is not a WPILib 2027 year "
                      "as GradleRIO writes it (2027, 2027_alpha5, 2027_beta1, ...)")
endif()
by_year(YEAR_KEY frcYear wpilibYear)
by_year(YEAR_VALUE 2026 ${CYBER_WPILIB_YEAR_2027})
by_year(COMMANDS_FILE WPILibNewCommands.json CommandsV2.json)

# CyberArmSubsystem and the commands: the robot controller, the command-based library, and whether
# the robot is enabled and the robot clock (µs) that CyberArmSubsystem.create wires up.
by_year(CONTROLLER roboRIO Systemcore)
by_year(COMMAND_PACKAGE edu.wpi.first.wpilibj2.command org.wpilib.command2)
by_year(ROBOT_STATE edu.wpi.first.wpilibj.DriverStation org.wpilib.driverstation.RobotState)
by_year(ROBOT_STATE_CLASS DriverStation RobotState)
by_year(ROBOT_CONTROLLER edu.wpi.first.wpilibj.RobotController org.wpilib.system.RobotController)
by_year(ENABLED DriverStation::isEnabled RobotState::isEnabled)
by_year(ROBOT_CLOCK RobotController::getFPGATime RobotController::getTime)

# CanStreamSetpointSource: the HAL's CAN stream. The roboRIO has one CAN bus; the Systemcore has
# five (CANBus.CAN_S0 to CAN_S4), and the team names the one the daemon's adapter is wired to, so
# in 2027 the constructor and withReferenceDevices take it first.
by_year(CAN_STREAM_IMPORTS [[
import edu.wpi.first.hal.CANStreamMessage;
import edu.wpi.first.hal.can.CANJNI;
import edu.wpi.first.hal.can.CANStreamOverflowException;
import edu.wpi.first.wpilibj.CAN;]] [[
import org.wpilib.hardware.bus.CANBus;
import org.wpilib.hardware.hal.can.CANJNI;
import org.wpilib.hardware.hal.can.CANStreamMessage;
import org.wpilib.hardware.hal.can.CANStreamOverflowException;
import org.wpilib.system.RobotController;]])
by_year(CAN_BUS_DOC "the roboRIO's CAN bus (WPILib 2026)"
        "the Systemcore CAN bus of the daemon's adapter (WPILib 2027)")
by_year(BUS_PARAMETER "" "CANBus bus")                # withReferenceDevices(BUS_PARAMETER)
by_year(BUS_PARAMETER_FIRST "" "CANBus bus, ")        # new CanStreamSetpointSource(BUS_PARAMETER_FIRST router)
by_year(BUS_ARGUMENT_FIRST "" "bus, ")                # the same, called
by_year(BUS_ID_ARGUMENT_FIRST "" "bus.value, ")       # CANJNI.openCANStreamSession(BUS_ID_ARGUMENT_FIRST id, ...)
by_year(MESSAGE_ID messageID messageId)               # CANStreamMessage's field
# The clock of the frames' timestamps, now (the roboRIO's CAN timer has its own base), and its tick.
by_year(FRAME_CLOCK "CAN.getTimestampBaseTime()" "RobotController.getTime()")
by_year(FRAME_TICK_MICROS 1000 1)
by_year(FRAME_CLOCK_DOC "ms on the timer of CAN.getTimestampBaseTime()"
        "µs on the robot clock, RobotController.getTime()")

# The layer's test (test/): the stand-ins' clocks and hooks, and a TalonFX as the year's Phoenix 6
# builds it (in 2027 on a Phoenix CANBus: src/standins2027/java/README.md).
by_year(TEST_IMPORTS [[
import edu.wpi.first.hal.can.CANJNI;
import edu.wpi.first.wpilibj.CAN;
import edu.wpi.first.wpilibj.DriverStation;
import edu.wpi.first.wpilibj.RobotController;]] [[
import org.wpilib.driverstation.RobotState;
import org.wpilib.hardware.bus.CANBus;
import org.wpilib.hardware.hal.can.CANJNI;
import org.wpilib.system.RobotController;]])
by_year(TEST_JOINT0_MOTOR "new TalonFX(11)" [[new TalonFX(11, new com.ctre.phoenix6.CANBus("can_s0"))]])
by_year(TEST_CLOCKS_DOC "The robot clock (µs) and the CAN timer (ms, another base: the layer must map between them)."
        "The robot clock, µs: the Systemcore HAL stamps CAN frames with it.")
by_year(TEST_SET_CLOCKS [[
    RobotController.standInFpgaTimeMicros = micros;
    CAN.standInTimeMs = 7_000 + micros / 1000;]] [[
    RobotController.standInTimeMicros = micros;]])
by_year(TEST_FRAME_TIMESTAMP "CAN.standInTimeMs - ageMicros / 1000" "nowMicros - ageMicros")
by_year(TEST_BUS "" CANBus.CAN_S2)
by_year(TEST_BUS_FIRST "" "CANBus.CAN_S2, ")  # CanStreamSetpointSource.withDevices(TEST_BUS_FIRST devices)
