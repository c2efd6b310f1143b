// The replay of the 3964R link's fuzz function (fuzz_link_3964r_replay): its
// seed corpus and parameters; fuzz_replay.cpp runs them.
#include "comm/camcon/table/frame_3964r.h"
#include "fuzz_replay.h"

#include <QByteArray>
#include <QList>

namespace {

using namespace cambench::comm::table;

// Random inputs are biased towards the control bytes.
constexpr char kInteresting[] = {kStx, kEtx, kDle, kNak, '\0', '\xFF', 'E', 'A', 'D'};

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

}  // namespace

int main() {
    // 5000 random inputs, most up to 120 bytes, one in 32 up to 2000: past the receive buffer.
    const cambench::fuzz::RandomInputs random{5000, 120, 2000, 20240602u};
    return cambench::fuzz::runReplay("fuzz_link_3964r_replay", seedCorpus(),
                                     QByteArray(kInteresting, sizeof kInteresting), random);
}
