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
class AsciiBackend : public FramingBackend {
public:
    AsciiBackend(Framing framing, int device, int pcNumber);

    Framing framing() const { return m_framing; }
    int device() const { return m_device; }
    void setDevice(int device);
    int pcNumber() const { return m_pcNumber; }
    // The block number the next request to `device` takes.
    int nextBlock(int device) const { return m_nextBlock[clampNumber(device)]; }
    // The block number of the request begun last (Multiuser).
    std::optional<MultiuserAddress> currentAddress() const { return m_address; }

    QString describe() const override;
    QString checkHint() const override;
    void beginRequest(const Request& request) override;
    BackendStep startAttempt(const Request& request, int attempt, qint64 nowMs) override;
    BackendStep feed(QByteArrayView bytes, qint64 nowMs) override;
    QByteArray resetInput() override;
    bool deduplicatesRetries() const override { return m_framing == Framing::Multiuser; }
    qint64 requestWireBytes(const Request& request) const override;
    qint64 replyWireBytes(const Request& request) const override;
    QByteArray maskForLog(const QByteArray& wire, bool outgoing) const override;

    static int clampNumber(int number) { return number < 0 ? 0 : (number > 63 ? 63 : number); }

private:
    bool isOurs(const Frame& frame) const;

    Framing m_framing;
    int m_device;
    int m_pcNumber;
    int m_nextBlock[64] = {};
    std::optional<MultiuserAddress> m_address;  // of the request begun last
    QByteArray m_wire;                          // the frame of the request begun last
    StreamDecoder m_decoder;
    QByteArray m_undecoded;  // received bytes of a frame not yet complete
};

}  // namespace cambench::comm
