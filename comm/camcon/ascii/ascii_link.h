#pragma once

#include "ascii_backend.h"
#include "catalogue.h"
#include "command_codec.h"

#include "comm/engine/request_engine.h"
#include "comm/transport/transport.h"

#include <atomic>
#include <functional>
#include <memory>

namespace cambench::comm {

// How the PC talks ASCII to a CamCon: the framing, the Multiuser numbers
// and the link's patience. Line timing comes from the connection.
struct AsciiSettings {
    Framing framing = Framing::Standard;
    int device = 0;              // Multiuser destination 0..63
    int pcNumber = 63;           // Multiuser own number
    int timeoutMs = 0;           // per attempt, normal commands; 0 = derived from the line
    int longTimeoutMs = 150000;  // !CA, !EE0000 (manual: up to 2 minutes)
    int retries = 3;             // further attempts after the first, where safe
    // Multiuser: make sure of the device's last block number before the
    // first request to it (see AsciiLink). Off only in tests that script
    // every frame a device receives.
    bool syncBlockNumbers = true;
};

// Speaks the CamCon ASCII protocol: turns a catalogue command into a
// request for the RequestEngine (with its retry policy, timeout class and
// the reply it waits for) and decodes the answer. In Multiuser framing it
// makes sure, before the first request to a device, that the device's last
// block number is not the one this run starts with (a repeated number is
// answered with the old reply, not executed). Lives in the worker thread.
class AsciiLink {
public:
    AsciiLink(Transport& transport, AsciiSettings settings, LineTiming line = {});
    // The same commands in another transport framing (Cam-BUS: a block on a
    // token bus): `backend` frames the requests, `settings.framing` stays
    // Standard (no block numbers; retries as the commands allow).
    AsciiLink(Transport& transport, AsciiSettings settings, LineTiming line,
              std::unique_ptr<FramingBackend> backend);

    const AsciiSettings& settings() const { return m_settings; }
    void setDevice(int device);
    void setTimeout(int ms);
    void setRetries(int retries);
    void setLineTiming(const LineTiming& line);

    // Set from any thread; an ongoing call returns Cancelled within ~20 ms.
    void setCancelFlag(const std::atomic_bool* flag) { m_engine.setCancelFlag(flag); }
    void setTrafficSink(std::function<void(const TrafficEntry&)> sink) {
        m_engine.setTrafficSink(std::move(sink));
    }

    // Sends `spec` with `fields` and returns the reply's fields. Device
    // errors (ERR) and :Z are returned at once, without retries.
    // `timeoutMs` overrides the per-attempt timeout when > 0.
    Result<Fields> call(const CommandSpec& spec, const Fields& fields = {}, int timeoutMs = 0);
    Result<Fields> call(char kind, const char* name, const Fields& fields = {}, int timeoutMs = 0);

    // A free-form request body ("IFGWG", "NF000003") with checksum added:
    // returns the reply frame's body. For the terminal and `raw`.
    Result<QByteArray> raw(char kind, const QByteArray& body, int timeoutMs = 0);

    // Bus scan (Multiuser): one ?UNIT to `device` under block number
    // `block`, a single attempt that gives the device `turnaroundMs` to
    // start answering (a fixed timeout of the settings wins). True when the
    // device answered anything under that block, which also serves as its
    // block-number sync; false when it stayed silent or the answer came
    // damaged. Leaves the link talking to `device`.
    Result<bool> ping(int device, int block, int turnaroundMs);

    // See RequestEngine.
    int lastAttempts() const { return m_engine.lastAttempts(); }
    bool lastCallMayHaveActedTwice() const { return m_engine.lastCallMayHaveActedTwice(); }
    bool lastCallHeardDevice() const { return m_engine.lastCallHeardDevice(); }
    using Stats = RequestEngine::Stats;
    const Stats& stats() const { return m_engine.stats(); }
    void resetStats() { m_engine.resetStats(); }
    RequestEngine& engine() { return m_engine; }
    FramingBackend& backend() { return *m_backend; }

    // The per-attempt timeout `spec` would get (for tests and messages).
    int attemptTimeoutMs(const CommandSpec& spec, const Fields& fields = {});

private:
    Result<Request> makeRequest(const CommandSpec& spec, const Fields& fields, int timeoutMs,
                                ReplyMatch* match);
    Status ensureBlockSync();
    void applySettings();

    AsciiSettings m_settings;
    LineTiming m_line;
    std::unique_ptr<FramingBackend> m_backend;  // an AsciiBackend unless another was given
    AsciiBackend* m_ascii = nullptr;            // m_backend when it is an AsciiBackend
    RequestEngine m_engine;
    bool m_synced[64] = {};
};

}  // namespace cambench::comm
