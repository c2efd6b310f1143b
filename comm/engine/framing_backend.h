#pragma once

#include "line_timing.h"
#include "request.h"

#include <QByteArray>
#include <QList>
#include <QString>

namespace cambench::comm {

// A piece of the incoming byte stream as the backend sees it.
struct Incoming {
    enum Kind {
        Message,  // a complete, intact frame for this connection: `message` is its content
        Damaged,  // a frame for this request that arrived damaged (checksum, size)
        Foreign,  // a frame for someone else (another device, another block): ignore
        Garbage,  // bytes outside any frame
    };
    Kind kind = Message;
    QByteArray message;  // Message: the protocol message, framing removed
    QByteArray wire;     // the wire bytes, for the traffic log
    QString detail;      // Damaged, Garbage: why
    // Message, Foreign: the station that sent an intact frame to this PC and
    // the sequence number it answers, where the framing names them (CamCon
    // Multiuser: device number and block number); -1 otherwise. A frame for
    // another PC, or a damaged one, names nobody: its header may be wrong.
    int source = -1;
    int sequence = -1;
};

// What the backend asks the engine to do after one of its calls.
struct BackendStep {
    QByteArray write;          // bytes to send now (a frame, a 3964R DLE, ...)
    bool quiet = false;        // `write` is bus housekeeping (a token answered): not logged
    bool sent = false;         // the request has left completely: its reply may come
    QString linkFailure;       // the link layer gave up on this attempt (3964R: no DLE)
    QList<Incoming> incoming;  // what completed in the bytes fed

    void append(BackendStep&& other) {
        quiet = (write.isEmpty() || quiet) && (other.write.isEmpty() || other.quiet);
        write += other.write;
        sent = sent || other.sent;
        if (linkFailure.isEmpty()) linkFailure = other.linkFailure;
        incoming += other.incoming;
    }
};

// One framing of one protocol: how a request becomes wire bytes and the
// byte stream becomes messages, in the manner of libmodbus' backend table.
// A backend is a state machine fed by bytes and by time; it never touches
// the transport, so each one is tested without a line. The RequestEngine
// owns the waiting, the retries and the cancel; the backend owns the bytes.
//
// A transparent framing (CamCon ASCII, MC-1, Compax3) sends the whole frame
// in startAttempt() with `sent` set. A link protocol with its own handshake
// (3964R, Cam-BUS) sends a first byte, answers the line from feed() and
// poll(), and sets `sent` once the peer has taken the request.
class FramingBackend {
public:
    virtual ~FramingBackend() = default;

    // The line the engine derives its timing from (e.g. for a gap timer
    // that ends a frame whose end was damaged); set before every request.
    virtual void setLineTiming(const LineTiming& line) { Q_UNUSED(line); }

    // A bus protocol addresses later requests to `device`; others ignore it.
    virtual void setDevice(int device) { Q_UNUSED(device); }

    // "Standard", "Multiuser device 5", "3964R (n96)": for messages.
    virtual QString describe() const = 0;
    // Where to look when the device stays silent, as a clause:
    // "check the cable, the baud rate and ...".
    virtual QString checkHint() const = 0;

    // A new request (not a retry) is about to start: e.g. take the next
    // sequence number. Retries of it reuse what this call set up.
    virtual void beginRequest(const Request& request) = 0;
    // Starts attempt `attempt` (1-based) of the request begun last.
    virtual BackendStep startAttempt(const Request& request, int attempt, qint64 nowMs) = 0;
    // Bytes from the line.
    virtual BackendStep feed(QByteArrayView bytes, qint64 nowMs) = 0;
    // Time passed: link-level timers (acknowledgement, character delay, a
    // frame that broke off).
    virtual BackendStep poll(qint64 nowMs) {
        Q_UNUSED(nowMs);
        return {};
    }
    // When poll() wants to run next (engine clock, ms); -1 = no timer.
    virtual qint64 nextTimerMs() const { return -1; }
    // Drops a partly received frame (before a request, before a retry) and
    // returns its bytes for the log.
    virtual QByteArray resetInput() = 0;

    // The line carries other users' bytes all the time (a token bus): a
    // byte says nothing of our device, only its frames and its
    // acknowledgement of our request (`sent`) do. The engine then keeps the
    // line read between requests (RequestEngine::serveLine).
    virtual bool carriesOtherTraffic() const { return false; }
    // Time the bus adds before a reply can come, beyond the bytes (a token
    // bus: the device answers at its next turn).
    virtual int replyLatencyMs() const { return 0; }

    // The protocol answers a repeated request without executing it again
    // (CamCon Multiuser block numbers): every retry is then safe.
    virtual bool deduplicatesRetries() const { return false; }
    // For a protocol whose answers do not say which request they answer (a
    // Compax3 answers a value, '>' or '!xxxx'), how long after a request's
    // first-byte time its answer may still come. After a silent attempt the
    // engine sends nothing else until the line has been quiet this long, and
    // takes what comes meanwhile as that request's answer: a late answer is
    // never taken for another request's. 0: the answers name their request
    // (command letters, a type, a sequence number), so the request's judge
    // tells a late one apart, and nothing is waited for.
    virtual int lateAnswerWindowMs() const { return 0; }
    // Wire bytes of `request` and of its longest reply, framing included:
    // the engine derives the attempt's timeout from them and the line.
    virtual qint64 requestWireBytes(const Request& request) const = 0;
    virtual qint64 replyWireBytes(const Request& request) const = 0;
    // The bytes as the traffic log may show them (secrets masked).
    virtual QByteArray maskForLog(const QByteArray& wire, bool outgoing) const {
        Q_UNUSED(outgoing);
        return wire;
    }
};

}  // namespace cambench::comm
