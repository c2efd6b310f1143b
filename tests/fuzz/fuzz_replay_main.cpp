// Runs the fuzz function without libFuzzer: over a fixed seed corpus and
// pseudo-random inputs from a fixed seed, so every normal build exercises it.
#include "comm/camcon/ascii/frame.h"

#include <QByteArray>
#include <QList>

#include <cstdint>
#include <cstdio>
#include <random>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

using namespace cambench::comm;

constexpr int kRandomInputs = 20000;

QByteArray wire(char lead, const QByteArray& body, std::optional<MultiuserAddress> address = {},
                bool hasChecksum = true) {
    Frame frame;
    frame.lead = lead;
    frame.body = body;
    frame.address = address;
    frame.hasChecksum = hasChecksum;
    return encodeFrame(frame);
}

QList<QByteArray> seedCorpus() {
    const MultiuserAddress pc{63, 4, 17};
    const MultiuserAddress device{4, 63, 17};
    return {
        {},
        "?IFGWG4C\r\n",
        ":IFOROKFB\r\n",
        ":EEOKA1\r\n",
        ":EEFFFF23\r\n",
        "?EE000175\r\n",
        "!EE00058F\r\n",
        ":EEERRFFFFFFD535\r\n",
        "!C0\r\n:C0OK\r\n",
        "?IFGWG4D\r\n",
        "?IFGWG4C\r?IFGWG4C\r\n",
        "\n\r\n\x1b\r\n",
        wire(':', QByteArray("EE0001\x20\r\x1b\n\x00\x1b\x1b\r\r", 15)),
        wire('?', "NF000003", pc) + wire(':', "NF0000000A0000001401", device),
        QByteArray("\x41\x82\x41\x82\xC3:EEOKA1\r\n"),
        QByteArray("\x7F\xBF\xFF?\x1b\r\n"),
        "?" + QByteArray(3000, 'A') + "\r\n?IFGWG4C\r\n",
        "?" + QByteArray(1200, '\x1b') + "\r\n",
        wire(':', "Z11.10.1994" + QByteArray(1, '\0')),
        wire('!', QByteArray(1019, 'B')),
    };
}

// The short seeds, to splice into random inputs.
QList<QByteArray> spliceFrames() {
    QList<QByteArray> frames;
    for (const QByteArray& seed : seedCorpus()) {
        if (!seed.isEmpty() && seed.size() <= 64) frames.append(seed);
    }
    return frames;
}

// Random inputs biased towards the bytes the decoder cares about, spliced
// with valid frames; one in 32 is long enough to overflow the frame cap.
QByteArray randomInput(std::mt19937& random) {
    static const char kInteresting[] = {'?', '!',    ':',    '\r',   '\n',   '\x1b', '0',    'F',
                                        'C', '\x40', '\x7F', '\x80', '\xBF', '\xC0', '\xFF', '\0'};
    static const QList<QByteArray> frames = spliceFrames();
    std::uniform_int_distribution<int> lengthOf(0, random() % 32 == 0 ? 2500 : 200);
    const int length = lengthOf(random);
    QByteArray input;
    while (input.size() < length) {
        switch (random() % 4) {
            case 0:
                input.append(char(random()));
                break;
            case 1:
            case 2:
                input.append(kInteresting[random() % sizeof kInteresting]);
                break;
            default:
                input.append(frames[random() % frames.size()]);
                break;
        }
    }
    return input;
}

}  // namespace

int main() {
    int runs = 0;
    for (const QByteArray& seed : seedCorpus()) {
        LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(seed.constData()),
                               size_t(seed.size()));
        ++runs;
    }
    std::mt19937 random(20240601u);
    for (int i = 0; i < kRandomInputs; ++i) {
        const QByteArray input = randomInput(random);
        LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(input.constData()),
                               size_t(input.size()));
        ++runs;
    }
    std::printf("fuzz_stream_decoder_replay: %d inputs, all invariants held\n", runs);
    return 0;
}
