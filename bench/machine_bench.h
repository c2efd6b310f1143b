#pragma once

namespace cambench::bench {

// A machine (issue 30): `cambench-cli machine backup` of a CamCon, an MC200
// and a Compax3, each a real throttled cambench-sim on a pseudo-terminal of
// its own at `baud`, first each device alone, then the three as one
// machine: the times and the ratio machine / slowest alone (the devices
// are on different ports, so the target is about 1; 1.2 at most); then the
// machine into an archive (issue 37: `--archive`, a first version and a
// backup with nothing changed), against the same target. The median of
// `repeat` runs each.
void benchMachine(int baud, int repeat);

}  // namespace cambench::bench
