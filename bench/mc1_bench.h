#pragma once

namespace cambench::bench {

// MC100/MC200 (issue 14): 1,000 variables and a 32 KiB range read from the
// throttled simulator of each variant at 9600 baud, block telegrams
// (RDBLOCK, RDMEM, RDMEM6) beside single ones (RDBYTE), each as time,
// wire bytes and the ratio to the wire limit (bytes x 10 / baud).
void benchMc1();

}  // namespace cambench::bench
