#pragma once

namespace cambench::bench {

// Cam-BUS (issue 16): an EEPROM backup and a program read of CamCon 3 over
// the throttled simulated bus at 38400 baud while two displays poll CamCon
// 3 and 7, as time, the bytes of the PC's own exchanges (its blocks and the
// replies, with the answers around them), the ratio to their wire limit
// (bytes x 10 / baud), and the displays' longest pause meanwhile.
void benchCamBus();

}  // namespace cambench::bench
