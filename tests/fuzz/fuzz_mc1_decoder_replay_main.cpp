// The replay of the MC-1 decoder's fuzz function (fuzz_mc1_decoder_replay):
// its seed corpus and parameters; fuzz_replay.cpp runs them.
#include "fuzz_replay.h"

#include <QByteArray>
#include <QList>

namespace {

// Random inputs are biased towards the bytes that start answers.
constexpr char kInteresting[] = {'\x80', '\x87', '\xFF', '\x04', '\x05',
                                 '\x02', '\xD7', '\xD0', '\x94', '\x00'};

QList<QByteArray> seedCorpus() {
    return {
        QByteArray::fromHex("0000"),
        QByteArray::fromHex("000004a0563412"),    // MC100 RDVAR answer 0x123456
        QByteArray::fromHex("8000ff0500000000"),  // probing: the MC200's width
        QByteArray::fromHex("0301ff80"),          // sync, then ACK
        QByteArray::fromHex("030187"),            // NAK
        QByteArray::fromHex("0306ff94dd033412"),  // status, PC 0x1234
        QByteArray::fromHex("0103d7" + QByteArray(58, 'a')),
        QByteArray::fromHex("000404a0563413"),  // a bad checksum
    };
}

}  // namespace

int main() {
    const cambench::fuzz::RandomInputs random{5000, 80, 400, 20261126u};
    return cambench::fuzz::runReplay("fuzz_mc1_decoder_replay", seedCorpus(),
                                     QByteArray(kInteresting, sizeof kInteresting), random);
}
