// libFuzzer target for the MC-1 answer decoder (Mc1Backend over
// takeMc1Answer). The same function runs in normal builds through
// fuzz_mc1_decoder_replay_main.cpp (fuzz_mc1_decoder_replay).
#include "comm/mc1/mc1_backend.h"
#include "fuzz_check.h"

#include <cstdint>

using namespace cambench::comm;

namespace {

// Requests whose answers differ in kind: ACK/NAK, fixed and variable length.
struct Ask {
    Mc1Op op;
    QByteArray parameters;
};

const Ask& askFor(quint8 selector) {
    static const Ask kAsks[] = {
        {Mc1Op::ReadVariable, QByteArray::fromHex("0100")},
        {Mc1Op::WriteBitInternal, QByteArray::fromHex("2240")},
        {Mc1Op::ReadByteExternal, QByteArray::fromHex("0c69")},
        {Mc1Op::ReadBlock, QByteArray::fromHex("00000038")},
        {Mc1Op::ReadMemory, QByteArray::fromHex("00107d")},
        {Mc1Op::ReadMemory6, QByteArray::fromHex("0010")},
        {Mc1Op::ProgramStatus, {}},
        {Mc1Op::AxisDataCommand, QByteArray::fromHex("010464000000")},
    };
    return kAsks[selector % (sizeof kAsks / sizeof kAsks[0])];
}

// Each message handed up is an ACK, a NAK, or an answer telegram of the
// length and opcode the request expects whose checksum holds.
void checkStep(const BackendStep& step, const Mc1Expectation& expected, bool probing) {
    for (const Incoming& in : step.incoming) {
        FUZZ_CHECK(!in.wire.isEmpty());
        if (in.kind != Incoming::Message) continue;
        if (in.message.size() == 1) {
            FUZZ_CHECK(quint8(in.message[0]) == kMc1Ack || quint8(in.message[0]) == kMc1Nak);
            continue;
        }
        const quint8 opcode = quint8(in.message[0]);
        const bool other = probing && expected.otherOpcode != 0 && opcode == expected.otherOpcode;
        FUZZ_CHECK(opcode == expected.opcode || other);
        FUZZ_CHECK(in.message.size() == (other ? expected.otherLength : expected.length));
        FUZZ_CHECK(mc1Checksum(in.message) == quint8(in.message[1]));
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    const auto variant = Mc1Variant(data[0] % 4);
    const bool probing = data[0] & 0x80;
    const Ask& ask = askFor(data[1]);
    const Mc1Telegram* row = mc1Find(variant, ask.op);
    if (!row) return 0;  // the variant lacks it: never sent
    Mc1Backend backend(variant);
    backend.setProbing(probing);
    Request request;
    request.message = *mc1Request(*row, ask.parameters);
    backend.beginRequest(request);
    const Mc1Expectation expected = Mc1Backend::expectationFor(variant, request.message, probing);
    qint64 now = 0;
    checkStep(backend.startAttempt(request, 1, now), expected, probing);
    // The rest in chunks of 1..8 bytes, their sizes taken from the input.
    std::size_t at = 2;
    while (at < size) {
        const std::size_t chunk = std::min<std::size_t>(size - at, 1 + data[at] % 8);
        const QByteArrayView bytes(reinterpret_cast<const char*>(data + at), qsizetype(chunk));
        now += data[at] % 7;
        checkStep(backend.feed(bytes, now), expected, probing);
        if (backend.nextTimerMs() >= 0 && now >= backend.nextTimerMs())
            checkStep(backend.poll(now), expected, probing);
        at += chunk;
    }
    (void)backend.resetInput();
    return 0;
}
