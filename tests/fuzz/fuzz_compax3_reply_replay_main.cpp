// The replay of the Compax3 reply parser's fuzz function
// (fuzz_compax3_reply_replay): its seed corpus and parameters;
// fuzz_replay.cpp runs them.
#include "fuzz_replay.h"

#include <QByteArray>
#include <QList>

namespace {

// Random inputs are biased towards the bytes that shape answers.
constexpr char kInteresting[] = {'\r', '\n', '*', '!', '>', '$', '.', '"', '0', 'F', '\0', '\x7F'};

QList<QByteArray> seedCorpus() {
    return {
        QByteArray("\xff"
                   "12.5\r"),
        QByteArray("\x05*1285\r"),
        QByteArray("\xff>\r!0004\r"),
        QByteArray("\x01*!0001\r*>\r"),
        QByteArray("\xff"
                   "Compax3 S025V2 F10 I10 T40 V04.02\r"),
        QByteArray("\xff!12\r\r$1F\r"),
        QByteArray("\xff"
                   "12\x01"
                   "3\r"),
    };
}

}  // namespace

int main() {
    const cambench::fuzz::RandomInputs random{5000, 80, 400, 20261126u};
    return cambench::fuzz::runReplay("fuzz_compax3_reply_replay", seedCorpus(),
                                     QByteArray(kInteresting, sizeof kInteresting), random);
}
