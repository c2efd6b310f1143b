// Runs the 3964R fuzz function without libFuzzer: over a fixed seed corpus
// and pseudo-random inputs from a fixed seed, so every normal build
// exercises it.
#include "comm/camcon/table/frame_3964r.h"

#include <QByteArray>
#include <QList>

#include <cstdint>
#include <cstdio>
#include <random>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

using namespace cambench::comm::table;

constexpr int kRandomInputs = 5000;

QByteArray transfer(const QByteArray& telegram) {
    return QByteArray(1, kStx) + encodeBlock3964r(telegram);
}

QList<QByteArray> seedCorpus() {
    return {
        {},
        QByteArray(1, kStx),
        QByteArray(1, kDle),
        QByteArray(1, kNak),
        QByteArray::fromHex("0204000701C32CC079100347"),
        QByteArray::fromHex("0241101042100310"),
        QByteArray::fromHex("0200004544050A0007FFFF10031A"),
        QByteArray::fromHex("0200000000100313"),
        QByteArray::fromHex("0204000701C32CC079100345"),  // BCC with the STX in it
        QByteArray::fromHex("0241100242"),                // DLE + STX inside a block
        QByteArray::fromHex("1010"),                      // DLE to STX, DLE to the block
        QByteArray::fromHex("1015101510151015101510151015"),
        transfer(QByteArray(600, '\x10')),
        QByteArray(1, kStx) + QByteArray(700, 'A') + QByteArray::fromHex("100300"),
        transfer("?\x01") + transfer(":\x01OK") + QByteArray::fromHex("10"),
    };
}

QList<QByteArray> spliceBlocks() {
    QList<QByteArray> blocks;
    for (const QByteArray& seed : seedCorpus()) {
        if (!seed.isEmpty() && seed.size() <= 64) blocks.append(seed);
    }
    return blocks;
}

// Random inputs biased towards the control bytes, spliced with whole
// transfers; one in 32 is long enough to overflow the receive buffer.
QByteArray randomInput(std::mt19937& random) {
    static const char kInteresting[] = {kStx, kEtx, kDle, kNak, '\0', '\xFF', 'E', 'A', 'D'};
    static const QList<QByteArray> blocks = spliceBlocks();
    std::uniform_int_distribution<int> lengthOf(0, random() % 32 == 0 ? 2000 : 120);
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
                input.append(blocks[random() % blocks.size()]);
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
    std::mt19937 random(20240602u);
    for (int i = 0; i < kRandomInputs; ++i) {
        const QByteArray input = randomInput(random);
        LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(input.constData()),
                               size_t(input.size()));
        ++runs;
    }
    std::printf("fuzz_link_3964r_replay: %d inputs, all invariants held\n", runs);
    return 0;
}
