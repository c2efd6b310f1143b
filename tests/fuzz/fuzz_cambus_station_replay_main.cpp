// The replay of the Cam-BUS station's fuzz function
// (fuzz_cambus_station_replay): its seed corpus and parameters;
// fuzz_replay.cpp runs them.
#include "fuzz_replay.h"

#include <QByteArray>
#include <QList>

namespace {

// Random inputs are biased towards the bytes that shape the bus: the token,
// DIDs, answers and RIDs of the PC 63 and of CamCon 3, breaks (FF 00 00).
constexpr char kInteresting[] = {'\xA5', '\x37', '\x3F', '\x03', '\x43', '\x83', '\x7F',
                                 '\xBF', '\xC3', '\xFF', '\x00', '\x06', '\x08'};

QList<QByteArray> seedCorpus() {
    return {
        // docs/protocols/cambus.md's worked example as the PC 63 hears it: RID 63, its token, 3's
        // room and acknowledgement, then 3's reply block.
        QByteArray::fromHex("3f01ffff20a5373f3f204320832"
                            "0a5370303433f20083a474e5230333742020520"),
        // Breaks, an RID search, tokens.
        QByteArray::fromHex("0300ff0000ff0000c0c140c2c3ffffa5370000a5370303"),
        // A damaged block and a repeat.
        QByteArray::fromHex("3f00a5370303433f083a474e523033374202ff083a474e52303337420205"),
    };
}

}  // namespace

int main() {
    const cambench::fuzz::RandomInputs random{5000, 120, 600, 20261126u};
    return cambench::fuzz::runReplay("fuzz_cambus_station_replay", seedCorpus(),
                                     QByteArray(kInteresting, sizeof kInteresting), random);
}
