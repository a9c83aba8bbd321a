package cyberplanner.roborio;

import static org.junit.jupiter.api.Assertions.assertEquals;

import cyberplanner.arm_setpoint_t;
import cyberplanner.roborio.SetpointGuard.Verdict;
import cyberplanner.roborio.can.Setpoint;
import java.util.List;
import lcm.lcm.LCM;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * ARM_SETPOINT as the setpoint source (simulation, a daemon on the controller): every message
 * reaches the guard whatever the poll rate, stamped when it arrived.
 */
class LcmSetpointSourceTest {
  long nowMicros = 5_000_000;

  static arm_setpoint_t setpoint(int sequence) {
    arm_setpoint_t m = new arm_setpoint_t();
    m.mode = arm_setpoint_t.MODE_MOVING;
    m.num_joints = 2;  // the arrays' length (docs/lcm.md, "Joints by index")
    m.position = new double[] {0.5, 1.0};
    m.velocity = new double[2];
    m.volts = new double[2];
    m.sequence = new byte[] {(byte) sequence, (byte) sequence};
    return m;
  }

  @Test
  void eachJointTakesItsOwnIndexOfTheArrays() throws Exception {
    LCM lcm = new LCM("memq://");
    CyberPlannerClient client = new CyberPlannerClient(lcm, Channels.DEFAULT, 1);
    LcmSetpointSource source = new LcmSetpointSource(client, () -> nowMicros);
    SetpointGuard guard = new SetpointGuard(JointChain.of("elevator", "arm"));
    arm_setpoint_t m = setpoint(0);
    m.position = new double[] {0.25, -1.5};
    m.velocity = new double[] {0.125, 2.5};
    m.volts = new double[] {0.37, -0.75};
    m.sequence = new byte[] {7, (byte) 200};
    lcm.publish("ARM_SETPOINT", m);
    ClientMemqTest.until(() -> {
      source.poll(guard, nowMicros);
      return guard.latest(1) != null;
    });
    assertEquals(new Setpoint(-1, 0.25, 0.125, 0.37, 7), guard.latest(0));
    assertEquals(new Setpoint(-1, -1.5, 2.5, -0.75, 200), guard.latest(1));
    assertEquals(Verdict.USE, guard.verdict(nowMicros));
    client.close();
  }

  @Test
  void aLossless200HzStreamPolledAt50HzLosesNoFrames() throws Exception {
    LCM lcm = new LCM("memq://");
    CyberPlannerClient client = new CyberPlannerClient(lcm, Channels.DEFAULT, 1);
    LcmSetpointSource source = new LcmSetpointSource(client, () -> nowMicros);
    SetpointGuard guard = new SetpointGuard(JointChain.of("elevator", "arm"));
    int sequence = 0;
    for (int loop = 0; loop < 50; ++loop) {
      for (int i = 0; i < 4; ++i, ++sequence) {
        if (loop == 20 && i == 1) continue;  // one message lost
        lcm.publish("ARM_SETPOINT", setpoint(sequence & 0xFF));
      }
      int last = (sequence - 1) & 0xFF;
      ClientMemqTest.until(() -> {  // one poll per loop once the loop's messages are in
        source.poll(guard, nowMicros);
        return guard.latest(0) != null && guard.latest(0).sequence() == last;
      });
      nowMicros += 20_000;
    }
    assertEquals(1, guard.lostFrames(0));
    assertEquals(1, guard.lostFrames(1));
    client.close();
  }

  @Test
  void aSetpointsAgeCountsFromItsArrivalNotFromThePoll() throws Exception {
    LCM lcm = new LCM("memq://");
    CyberPlannerClient client = new CyberPlannerClient(lcm, Channels.DEFAULT, 1);
    LcmSetpointSource source = new LcmSetpointSource(client, () -> nowMicros);
    SetpointGuard guard = new SetpointGuard(JointChain.of("elevator", "arm"));
    List<arm_setpoint_t> delivered = ClientMemqTest.collect(lcm, "ARM_SETPOINT", arm_setpoint_t::new);
    lcm.publish("ARM_SETPOINT", setpoint(0));
    ClientMemqTest.until(() -> delivered.size() == 1);  // LCM handed it to the client (first) and to us
    nowMicros += 60_000;  // the loop's first poll after it arrived comes 60 ms later
    source.poll(guard, nowMicros);
    assertEquals(Verdict.SETPOINT_STALE, guard.verdict(nowMicros));
    client.close();
  }

  @ParameterizedTest
  @ValueSource(ints = {1, 2, 3})
  void aChainOfNJointsTakesMessagesOfNJointsOnly(int n) throws Exception {
    LCM lcm = new LCM("memq://");
    CyberPlannerClient client = new CyberPlannerClient(lcm, Channels.DEFAULT, 1);
    LcmSetpointSource source = new LcmSetpointSource(client, () -> nowMicros);
    SetpointGuard guard = new SetpointGuard(JointChain.of(List.of("a", "b", "c").subList(0, n)));
    for (int count : new int[] {n + 1, n}) {  // another robot's first: ignored
      arm_setpoint_t m = setpoint(0);
      m.num_joints = (byte) count;
      m.position = new double[count];
      m.velocity = new double[count];
      m.volts = new double[count];
      m.sequence = new byte[count];
      for (int i = 0; i < count; ++i) {
        m.position[i] = 10 * count + i;  // says the message's joint count and the joint
        m.velocity[i] = -i;
        m.volts[i] = 0.5 * i;
        m.sequence[i] = (byte) (3 + i);
      }
      lcm.publish("ARM_SETPOINT", m);
    }
    ClientMemqTest.until(() -> {
      source.poll(guard, nowMicros);
      return guard.latest(n - 1) != null;
    });
    for (int i = 0; i < n; ++i) assertEquals(new Setpoint(-1, 10 * n + i, -i, 0.5 * i, 3 + i), guard.latest(i));
    assertEquals(Verdict.USE, guard.verdict(nowMicros));
    client.close();
  }
}
