#include "fuzz_replay.h"

#include <cstdio>
#include <random>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace cambench::fuzz {

namespace {

// Seeds this short are whole frames or transfers worth splicing in.
constexpr int kMaxSpliceBytes = 64;

QList<QByteArray> splicePieces(const QList<QByteArray>& seeds) {
    QList<QByteArray> pieces;
    for (const QByteArray& seed : seeds) {
        if (!seed.isEmpty() && seed.size() <= kMaxSpliceBytes) pieces.append(seed);
    }
    return pieces;
}

QByteArray randomInput(const RandomInputs& lengths, const QByteArray& interesting,
                       const QList<QByteArray>& pieces, std::mt19937& random) {
    std::uniform_int_distribution<int> lengthOf(
        0, random() % 32 == 0 ? lengths.longLengthMax : lengths.shortLengthMax);
    const int length = lengthOf(random);
    QByteArray input;
    while (input.size() < length) {
        switch (random() % 4) {
            case 0:
                input.append(char(random()));
                break;
            case 1:
            case 2:
                input.append(interesting[random() % interesting.size()]);
                break;
            default:
                input.append(pieces[random() % pieces.size()]);
                break;
        }
    }
    return input;
}

void runOne(const QByteArray& input) {
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(input.constData()),
                           size_t(input.size()));
}

}  // namespace

int runReplay(const char* name, const QList<QByteArray>& seeds, const QByteArray& interesting,
              const RandomInputs& random) {
    int runs = 0;
    for (const QByteArray& seed : seeds) {
        runOne(seed);
        ++runs;
    }
    const QList<QByteArray> pieces = splicePieces(seeds);
    std::mt19937 generator(random.seed);
    for (int i = 0; i < random.count; ++i) {
        runOne(randomInput(random, interesting, pieces, generator));
        ++runs;
    }
    std::printf("%s: %d inputs, all invariants held\n", name, runs);
    return 0;
}

}  // namespace cambench::fuzz
