package cyberplanner.roborio.wpilib2027;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
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
    CanStreamSetpointSource source = CanStreamSetpointSource.withReferenceDevices(CANBus.CAN_S2);
    assertEquals(List.of(CANBus.CAN_S2.value), CANJNI.standInBuses);
    source.close();
  }
}
