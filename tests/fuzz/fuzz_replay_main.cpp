// The replay of the stream decoder's fuzz function (fuzz_stream_decoder_replay):
// its seed corpus and parameters; fuzz_replay.cpp runs them.
#include "comm/camcon/ascii/frame.h"
#include "fuzz_replay.h"

#include <QByteArray>
#include <QList>

namespace {

using namespace cambench::comm;

// Random inputs are biased towards the bytes the decoder cares about.
constexpr char kInteresting[] = {'?', '!',    ':',    '\r',   '\n',   '\x1b', '0',    'F',
                                 'C', '\x40', '\x7F', '\x80', '\xBF', '\xC0', '\xFF', '\0'};

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

}  // namespace

int main() {
    // 20000 random inputs, most up to 200 bytes, one in 32 up to 2500: past the frame cap.
    const cambench::fuzz::RandomInputs random{20000, 200, 2500, 20240601u};
    return cambench::fuzz::runReplay("fuzz_stream_decoder_replay", seedCorpus(),
                                     QByteArray(kInteresting, sizeof kInteresting), random);
}
