#pragma once

#include "frame.h"
#include "stream_decoder.h"

#include "comm/engine/framing_backend.h"

#include <optional>

namespace cambench::comm {

// The CamCon ASCII framings (notes 1) as a FramingBackend: Standard (point
// to point, no header) and Multiuser (three header bytes with source,
// destination and a block number per destination device). A request message
// is the lead character and the body ("?NF000101"); the backend adds header,
// ESC escaping, checksum and CR LF, and hands up replies the same way.
//
// What arrives while a request waits is sorted so that a damaged reply ends
// the attempt at once instead of its timeout: a bad checksum, a reply line
// whose lead was hit (it still shows our command's first letters, or in
// Multiuser our header), and, by a gap timer, a frame that stopped before
// its CR LF.
class AsciiBackend : public FramingBackend {
public:
    AsciiBackend(Framing framing, int device, int pcNumber);

    Framing framing() const { return m_framing; }
    int device() const { return m_device; }
    void setDevice(int device) override;
    int pcNumber() const { return m_pcNumber; }
    // The block number the next request to `device` takes.
    void setNextBlock(int device, int block) { m_nextBlock[clampNumber(device)] = block & 63; }

    void setLineTiming(const LineTiming& line) override { m_gapMs = line.frameGapMs(); }
    QString describe() const override;
    QString checkHint() const override;
    void beginRequest(const Request& request) override;
    BackendStep startAttempt(const Request& request, int attempt, qint64 nowMs) override;
    BackendStep feed(QByteArrayView bytes, qint64 nowMs) override;
    BackendStep poll(qint64 nowMs) override;
    qint64 nextTimerMs() const override { return m_gapDeadline; }
    QByteArray resetInput() override;
    bool deduplicatesRetries() const override { return m_framing == Framing::Multiuser; }
    qint64 requestWireBytes(const Request& request) const override;
    qint64 replyWireBytes(const Request& request) const override;
    QByteArray maskForLog(const QByteArray& wire, bool outgoing) const override;

    static int clampNumber(int number) { return number < 0 ? 0 : (number > 63 ? 63 : number); }

private:
    Incoming classify(const DecodeEvent& event);
    Incoming classifyGarbage(const DecodeEvent& event);
    bool isOurs(const Frame& frame) const;
    // Multiuser: how many of the three header bytes of `wire` are those our
    // reply carries (0 without a request or in Standard framing).
    int headerMatches(QByteArrayView wire) const;
    bool looksLikeOurReply(QByteArrayView line) const;
    bool isEcho(QByteArrayView line) const;
    void armGapTimer(qint64 nowMs);

    Framing m_framing;
    int m_device;
    int m_pcNumber;
    int m_nextBlock[64] = {};
    std::optional<MultiuserAddress> m_address;  // of the request begun last
    QByteArray m_wire;                          // the frame of the request begun last
    bool m_secretRequest = false;               // it carries or asks for secrets (!USER, ?EE, ...)
    StreamDecoder m_decoder;
    QByteArray m_undecoded;    // received bytes of a frame not yet complete
    QByteArray m_garbageLine;  // bytes outside frames since the last line end
    int m_gapMs = 30;
    qint64 m_gapDeadline = -1;  // when unfinished input counts as broken off
};

}  // namespace cambench::comm
