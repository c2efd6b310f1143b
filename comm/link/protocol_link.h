#pragma once

#include "comm/protocol/catalogue.h"
#include "comm/protocol/command_codec.h"
#include "comm/protocol/stream_decoder.h"
#include "comm/transport/transport.h"

#include <QDateTime>

#include <atomic>
#include <functional>
#include <memory>
#include <optional>

namespace cambench::comm {

struct LinkSettings {
    Framing framing = Framing::Standard;
    int device = 0;        // Multiuser destination 0..63
    int pcNumber = 63;     // Multiuser own number
    int timeoutMs = 1000;  // per attempt, normal commands
    int longTimeoutMs = 150000;  // !CA, !EE0000 (manual: up to 2 minutes)
    int retries = 3;       // further attempts after the first
};

// One line of the traffic log. User numbers are masked by the link before
// the entry leaves it (the ?USER/!USER number fields).
struct TrafficEntry {
    QDateTime time;
    bool outgoing = true;
    QByteArray bytes;      // wire bytes, secrets overwritten with '*'
};

// Speaks the ASCII protocol over a Transport: frames a request, waits for
// the matching reply, retries on timeout or checksum error (Multiuser: with
// the same block number), keeps a block counter per destination device.
// Lives in the worker thread; every call blocks that thread only.
class ProtocolLink {
public:
    ProtocolLink(Transport& transport, LinkSettings settings);

    const LinkSettings& settings() const { return m_settings; }
    void setDevice(int device) { m_settings.device = device; }
    void setTimeout(int ms) { m_settings.timeoutMs = ms; }
    void setRetries(int retries) { m_settings.retries = retries; }

    // Set from any thread; an ongoing call returns Cancelled within ~50 ms.
    void setCancelFlag(const std::atomic_bool* flag) { m_cancel = flag; }
    void setTrafficSink(std::function<void(const TrafficEntry&)> sink) { m_sink = std::move(sink); }

    // Sends `spec` with `fields` and returns the reply's fields. Device
    // errors (ERR) and :Z are returned at once, without retries.
    // `timeoutMs` overrides the per-attempt timeout when > 0.
    Result<Fields> call(const CommandSpec& spec, const Fields& fields = {}, int timeoutMs = 0);
    Result<Fields> call(char kind, const char* name, const Fields& fields = {}, int timeoutMs = 0);

    // A free-form request body ("IFGWG", "NF000003") with checksum added:
    // returns the reply frame's body. For the terminal and `raw`.
    Result<QByteArray> raw(char kind, const QByteArray& body, int timeoutMs = 0);

    // How many times the last call sent its request. Above 1 an earlier
    // attempt may have reached the device and been executed although its
    // reply was lost: in Standard framing (no block numbers) a repeated
    // cursor step (?NN, ?USER01) or a repeated insert or EEPROM block then
    // acts twice, and the caller has to re-synchronise (see CamConClient).
    int lastAttempts() const { return m_lastAttempts; }
    // Whether bytes came back during the last call, valid or not: with
    // stale input dropped before each request, the device then received
    // the request and answered, so a failed call may still have acted.
    bool lastCallHeardDevice() const { return m_lastHeardDevice; }

    // Counters for benchmarks and logs.
    struct Stats {
        qint64 bytesSent = 0;
        qint64 bytesReceived = 0;
        int requests = 0;
        int retries = 0;
        int badFrames = 0;
    };
    const Stats& stats() const { return m_stats; }
    void resetStats() { m_stats = {}; }

private:
    // What a reply frame means to the request waiting for it; Retry says
    // why in `problem`.
    enum class Verdict { Accept, Ignore, Retry };
    using Judge = std::function<Verdict(const Frame&, QString& problem)>;

    // Sends `body` (framed, with the next block number in Multiuser) and
    // retries until `judge` accepts a reply, the attempts run out or the
    // cancel flag is set. `expectReply` false returns after writing.
    Result<Frame> exchange(const QString& label, char kind, const QByteArray& body,
                           int timeoutMs, bool expectReply, const Judge& judge);
    // One attempt's wait: the accepted frame, or nothing when the attempt
    // failed (`problem` says why) and another may follow.
    Result<std::optional<Frame>> awaitReply(const std::optional<MultiuserAddress>& request,
                                            int timeoutMs, const Judge& judge,
                                            QString& problem);
    Verdict judgeFrame(const DecodeEvent& event, const std::optional<MultiuserAddress>& request,
                       const Judge& judge, QString& problem);
    int timeoutFor(const CommandSpec* spec, const QByteArray& body, int timeoutMs) const;
    QString noReplyMessage(const QString& label, int attempts, int timeoutMs,
                           const QString& problem) const;
    bool cancelled() const { return m_cancel && m_cancel->load(); }
    void report(const QByteArray& bytes, bool outgoing);
    // Logs bytes left from an earlier exchange and starts the decoder afresh.
    void dropStaleInput();

    Transport& m_transport;
    LinkSettings m_settings;
    const std::atomic_bool* m_cancel = nullptr;
    std::function<void(const TrafficEntry&)> m_sink;
    std::unique_ptr<StreamDecoder> m_decoder;
    QByteArray m_undecoded;  // received bytes of a frame not yet complete
    int m_nextBlock[64] = {};
    Stats m_stats;
    int m_lastAttempts = 0;
    bool m_lastHeardDevice = false;
};

}  // namespace cambench::comm
