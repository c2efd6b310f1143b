// libFuzzer target for the frame decoder. The same function runs in normal
// builds through fuzz_replay_main.cpp (fuzz_stream_decoder_replay).
#include "comm/camcon/ascii/stream_decoder.h"
#include "fuzz_check.h"

#include <QLoggingCategory>

#include <cstdint>

using namespace cambench::comm;

namespace {

struct Setup {
    Framing framing;
    const char* leads;
    bool checksums;
};

constexpr Setup kSetups[] = {
    {Framing::Standard, ":", true},    {Framing::Standard, "?!", true},
    {Framing::Multiuser, ":", true},   {Framing::Multiuser, "?!", true},
    {Framing::Standard, "?!:", false}, {Framing::Multiuser, "?!:", false},
};

StreamDecoder makeDecoder(const Setup& setup) {
    StreamDecoder decoder(setup.framing, setup.leads);
    decoder.setChecksumEnabled(setup.checksums);
    return decoder;
}

// A frame that decoded fine must survive encodeFrame and a fresh decoder.
void checkReencodes(const Frame& frame, const Setup& setup) {
    StreamDecoder again = makeDecoder(setup);
    const QList<DecodeEvent> events = again.feed(encodeFrame(frame));
    FUZZ_CHECK(events.size() == 1);
    FUZZ_CHECK(events[0].kind == DecodeEvent::FrameOk);
    FUZZ_CHECK(events[0].frame == frame);
}

// Frames, bad frames and oversized drops do not depend on how reads split the
// stream; garbage may be reported in different pieces.
QList<DecodeEvent> withoutGarbage(const QList<DecodeEvent>& events) {
    QList<DecodeEvent> out;
    for (const DecodeEvent& event : events) {
        if (event.kind != DecodeEvent::Garbage) out.append(event);
    }
    return out;
}

void runSetup(const uint8_t* data, size_t size, const Setup& setup) {
    const QByteArrayView input(reinterpret_cast<const char*>(data), qsizetype(size));

    StreamDecoder chunked = makeDecoder(setup);
    QList<DecodeEvent> chunkedEvents;
    QByteArray reported;
    // Chunk sizes derived from the input, so that a crash reproduces.
    quint32 state = quint32(size) * 2654435761u + (size ? data[0] : 0u);
    qsizetype position = 0;
    while (position < input.size()) {
        state = state * 1103515245u + 12345u;
        const qsizetype chunk = qMin<qsizetype>(1 + (state >> 16) % 97, input.size() - position);
        const QList<DecodeEvent> events = chunked.feed(input.sliced(position, chunk));
        position += chunk;
        for (const DecodeEvent& event : events) {
            FUZZ_CHECK(!event.raw.isEmpty());
            reported += event.raw;
            if (event.kind == DecodeEvent::FrameOk || event.kind == DecodeEvent::BadChecksum) {
                FUZZ_CHECK(QByteArrayView(setup.leads).contains(event.frame.lead));
                FUZZ_CHECK(event.frame.address.has_value() ==
                           (setup.framing == Framing::Multiuser));
            }
            if (event.kind == DecodeEvent::FrameOk) checkReencodes(event.frame, setup);
        }
        chunkedEvents += events;
        FUZZ_CHECK(chunked.pendingBytes() <= StreamDecoder::kMaxFrameBytes);
        // Every byte is either reported exactly once, in order, or pending.
        FUZZ_CHECK(reported.size() + chunked.pendingBytes() == position);
        FUZZ_CHECK(input.first(reported.size()) == QByteArrayView(reported));
    }

    StreamDecoder whole = makeDecoder(setup);
    const QList<DecodeEvent> wholeEvents = withoutGarbage(whole.feed(input));
    const QList<DecodeEvent> splitEvents = withoutGarbage(chunkedEvents);
    FUZZ_CHECK(wholeEvents.size() == splitEvents.size());
    for (qsizetype i = 0; i < wholeEvents.size(); ++i) {
        FUZZ_CHECK(wholeEvents[i].kind == splitEvents[i].kind);
        FUZZ_CHECK(wholeEvents[i].frame == splitEvents[i].frame);
        FUZZ_CHECK(wholeEvents[i].raw == splitEvents[i].raw);
    }
    FUZZ_CHECK(whole.pendingBytes() == chunked.pendingBytes());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    // Oversized frames log a warning each; millions of them only slow the run.
    static const bool quiet =
        (QLoggingCategory::setFilterRules(QStringLiteral("cambench.*=false")), true);
    Q_UNUSED(quiet);
    for (const Setup& setup : kSetups) runSetup(data, size, setup);
    return 0;
}
