#pragma once

namespace cambench::bench {

// Cam-BUS (issue 16): an EEPROM backup and a program read of CamCon 3 over
// the throttled simulated bus at 38400 baud while two displays poll CamCon
// 3 and 7, as time, the bytes of the PC's own exchanges (its blocks and the
// replies, with the answers around them), the ratio to their wire limit
// (bytes x 10 / baud), and the displays' longest pause meanwhile.
void benchCamBus();

// Issue 39: the real cambench-cli against a real cambench-sim Cam-BUS on a
// pseudo-terminal at the bus's own timing (38400 baud, T = 10 ms), CamCons
// 3 and 7, display 12 polling 3: a backup, restore and verify of CamCon
// 3's EEPROM and an info of 7, each command's time and exit code, and the
// PC's answer times as the simulated users saw them (median, worst,
// missed), from the simulator's summary.
void benchCamBusAnswers();

}  // namespace cambench::bench
