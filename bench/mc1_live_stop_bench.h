#pragma once

namespace cambench::bench {

// STOP of every axis of an MC200 V2 on a live line (issue 35): the
// throttled simulator on a pseudo-terminal at 9600 baud, reached through
// the real worker and QSerialPort while a poll runs; the axes known, the
// axes not known, and the controller not identified either. From the
// moment STOP is asked to the last stop's acknowledgement, beside the
// wire limit of the stops and their answers (bytes x 10 / baud).
void benchMc1LiveStop();

}  // namespace cambench::bench
