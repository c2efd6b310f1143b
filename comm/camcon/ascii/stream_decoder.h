#pragma once

#include "frame.h"

#include <QList>
#include <QString>

namespace cambench::comm {

// What one completed (or abandoned) piece of the stream turned out to be.
struct DecodeEvent {
    enum Kind {
        FrameOk,      // a complete frame with a correct checksum
        BadChecksum,  // complete frame, checksum wrong or missing
        Oversized,    // no CR within kMaxFrameBytes: dropped, decoder resynchronised
        Garbage,      // bytes outside any frame that were skipped
    };
    Kind kind = FrameOk;
    Frame frame;     // valid for FrameOk and BadChecksum
    QByteArray raw;  // the wire bytes this event consumed
    QString detail;  // for logs and error messages
};

// Incremental, pure frame decoder: feed() any piece of the byte stream and
// get back what completed. Copes with garbage, frames split across reads and
// several frames in one read. A frame starts at a lead character ('?', '!',
// ':') - preceded by the 3 header bytes in Multiuser framing - and ends at a
// CR LF whose CR is not escaped by ESC.
class StreamDecoder {
public:
    static constexpr int kMaxFrameBytes = 1024;

    // `acceptLeads` lists the lead characters that may start a frame: ":" on
    // the PC side, "?!" on the device side.
    StreamDecoder(Framing framing, QByteArray acceptLeads);

    // With checksums off (!C0) frames carry none and none is checked.
    void setChecksumEnabled(bool enabled) { m_checksumEnabled = enabled; }
    Framing framing() const { return m_framing; }

    QList<DecodeEvent> feed(QByteArrayView bytes);
    void reset();
    // Bytes held for an incomplete frame.
    int pendingBytes() const { return int(m_buffer.size()); }

private:
    enum class State {
        Hunt,     // looking for a frame start; m_buffer holds a partial Multiuser header
        Body,     // inside a frame; m_buffer holds its wire bytes so far
        Discard,  // skipping the rest of an oversized frame up to its CR LF
    };

    void huntByte(char c, QList<DecodeEvent>& events);
    void bodyByte(char c, QList<DecodeEvent>& events);
    void discardByte(char c, QList<DecodeEvent>& events);
    void completeFrame(QList<DecodeEvent>& events);
    bool isFrameStartPrefix(QByteArrayView bytes) const;
    void startBody();
    void addGarbage(QByteArrayView bytes, const QString& reason, QList<DecodeEvent>& events);
    void flushGarbage(QList<DecodeEvent>& events);

    Framing m_framing;
    QByteArray m_acceptLeads;
    bool m_checksumEnabled = true;
    QByteArray m_buffer;
    State m_state = State::Hunt;
    QByteArray m_body;       // unescaped bytes after the lead
    bool m_escaped = false;  // an ESC was read: the next byte is literal
    bool m_crSeen = false;   // an unescaped CR waits for its LF
    QByteArray m_garbage;    // skipped bytes not yet reported
    QString m_garbageReason;
};

}  // namespace cambench::comm
