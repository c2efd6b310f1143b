#pragma once

#include "mc1_catalogue.h"

#include "comm/engine/request_engine.h"

namespace cambench::comm {

// The engine settings of an MC-1 connection (binary or ASCII): an answer
// is awaited 0.5 s beyond the wire time, since the controller NAKs a
// telegram cut short only after its character timeout (the emulator's:
// 100 ms), and that late NAK must not pass for the next request's answer.
EngineSettings mc1EngineSettings(LineTiming line, int retries, int timeoutMs);

// Whether `error` is the controller's refusal (a NAK), as Mc1Link reports it.
bool isMc1Refusal(const Error& error);

// MC-1 telegrams through the request engine: each sent with the repeat
// rule its catalogue row (and, for axis commands, its command) gives, its
// answer checked. A NAK is the controller's refusal (unknown to the
// variant, bad parameters) and is reported as such.
class Mc1Link {
public:
    Mc1Link(RequestEngine& engine, Mc1Variant variant) : m_engine(engine), m_variant(variant) {}

    Mc1Variant variant() const { return m_variant; }
    void setVariant(Mc1Variant variant) { m_variant = variant; }

    // The answer data (empty for an ACK); an error names the telegram.
    // `maxAttempts` > 0 caps the attempts below what the repeat rule allows
    // (a STOP of every axis gives each stop one attempt before any repeat).
    Result<QByteArray> exchange(Mc1Op op, const QByteArray& parameters, int maxAttempts = 0);
    // The last exchange went out more than once although it acts: the
    // caller must re-read the state and say what it found.
    bool lastMayHaveActedTwice() const { return m_engine.lastCallMayHaveActedTwice(); }

private:
    RequestEngine& m_engine;
    Mc1Variant m_variant;
};

}  // namespace cambench::comm
