package cyberplanner.roborio.wpilib2027;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.wpilib.hardware.bus.CANBus;
import org.wpilib.hardware.hal.can.CANJNI;

/**
 * What only the 2027 layer has (the shared layer test is Wpilib2027LayerTest, written from
 * src/wpilib/test): the Systemcore has several CAN buses, and the stream reads the one it is given.
 */
class CanStreamBusTest {
  @Test
  void theStreamIsOpenedOnTheGivenBus() {
    CANJNI.standInReset();
    CanStreamSetpointSource source = CanStreamSetpointSource.withDefaultDevices(CANBus.CAN_S2);
    CanStreamSetpointSource named = CanStreamSetpointSource.withDevices(CANBus.CAN_S4, Map.of("pivot", 5, "status", 6));
    assertEquals(List.of(CANBus.CAN_S2.value, CANBus.CAN_S4.value), CANJNI.standInBuses);
    source.close();
    named.close();
  }
}
