#pragma once

namespace cambench::bench {

// MC100/MC200 (issue 14): 1,000 variables and a 32 KiB range read from the
// throttled simulator of each variant at 9600 baud, block telegrams
// (RDBLOCK, RDMEM, RDMEM6) beside single ones (RDBYTE), each as time,
// wire bytes and the ratio to the wire limit (bytes x 10 / baud). First
// STOP of every axis (issue 27): 8 and 3 axes, and 8 with one stop's
// answer lost, to the last acknowledgement; and on a live line with a
// poll running (mc1_live_stop_bench.h); `stopOnly`: those alone.
void benchMc1(bool stopOnly = false);

}  // namespace cambench::bench
