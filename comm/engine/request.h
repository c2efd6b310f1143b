#pragma once

#include <QByteArray>
#include <QString>

#include <functional>

namespace cambench::comm {

// How long a device may work before it answers.
enum class TimeoutClass {
    Normal,  // answers as soon as it has read the request
    Long,    // works first: CamCon !CA (up to 2 min), !EE0000 (erases the EEPROM) and
             // the empty !EE block that ends a restore (starts the device)
};

// Whether a request may be sent again after its reply was lost. A protocol
// without sequence numbers (CamCon Standard, MC-1, Compax3) executes a
// repeated request again; one that numbers its requests (CamCon Multiuser)
// answers a repeat without executing it, which makes every retry safe there
// (FramingBackend::deduplicatesRetries).
enum class RetryPolicy {
    Idempotent,  // executing twice does no harm (queries, absolute writes)
    CheckAfter,  // may act twice (a cursor step, an insert): retry, but the
                 // caller must check the device when lastCallMayHaveActedTwice()
    Never,       // may act twice and cannot be checked (a relative move):
                 // one attempt unless the protocol deduplicates
};

// What a reply means to the request waiting for it.
enum class Verdict {
    Accept,  // the answer: the engine returns it
    Ignore,  // not for this request (an echo, an unrelated frame): keep waiting
    Retry,   // ours but unusable (malformed): this attempt failed
    Resend,  // the device answered an older request instead of executing this one (a
             // Multiuser block number it had seen last): send again as a new request
};

// One request as the engine sends it: a protocol message the framing
// backend wraps for the wire, and how to treat its reply.
struct Request {
    QString label;              // for messages and logs: "?NF", "RK512 read DB 5"
    QByteArray message;         // the protocol message; the backend adds the framing
    int longestReplyBytes = 0;  // protocol message bytes, for the line-derived timeout
    TimeoutClass timeout = TimeoutClass::Normal;
    RetryPolicy retry = RetryPolicy::Idempotent;
    bool expectReply = true;
    int fixedTimeoutMs = 0;  // > 0: this per-attempt timeout instead of the derived one
    int maxAttempts = 0;     // > 0: at most this many attempts (a bus scan: 1)
    // >= 0: the device's turnaround for this request instead of the line's
    // (a bus scan's first look gives each number only a short moment).
    int turnaroundMs = -1;
    // Silence is an expected answer (a bus scan asking an empty address):
    // no warning in the log when every attempt stays silent.
    bool silenceExpected = false;
    // Can start or continue motion or change a drive's power (a move, a jog,
    // homing, a set's objects and its select and start, enable, a program's
    // start or step, a restore's writes): refused, before it leaves, for a
    // job asked before the last STOP (stop_generation.h). Set by the family
    // code that builds the request; a stop command never sets it.
    bool motion = false;
    // Judges each valid reply message; none = the first valid reply is the answer.
    std::function<Verdict(const QByteArray& reply, QString& problem)> judge;
    // Long requests: an idempotent request the engine sends when the device
    // has been silent for a while, to tell "still busy" (the probe gets no
    // answer either) from "the answer was lost" (the probe is answered).
    std::function<Request()> probe;
};

}  // namespace cambench::comm
