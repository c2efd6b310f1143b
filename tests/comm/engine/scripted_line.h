#pragma once

// A fake framing and a scripted line on a virtual clock, for RequestEngine
// tests that check what was sent when, to the millisecond, without waiting.

#include "comm/engine/framing_backend.h"
#include "comm/transport/transport.h"

#include <QList>

#include <functional>

namespace cambench::comm::test {

// Milliseconds that pass only when the line "waits".
struct VirtualClock {
    qint64 nowMs = 0;
};

// A line framing as simple as it gets: a request is its message, '#', its
// sequence number and '\n'; every line that comes back is a reply: "!..."
// arrives damaged, "~..." is for someone else, anything else is a message.
class FakeBackend : public FramingBackend {
public:
    explicit FakeBackend(bool deduplicates = false) : m_deduplicates(deduplicates) {}

    QString describe() const override { return QStringLiteral("the fake device"); }
    QString checkHint() const override { return QStringLiteral("check the script"); }
    void beginRequest(const Request& request) override;
    BackendStep startAttempt(const Request& request, int attempt, qint64 nowMs) override;
    BackendStep feed(QByteArrayView bytes, qint64 nowMs) override;
    QByteArray resetInput() override;
    bool deduplicatesRetries() const override { return m_deduplicates; }
    int lateAnswerWindowMs() const override { return lateWindowMs; }
    // The late-answer window this fake protocol claims (0: none).
    int lateWindowMs = 0;
    qint64 requestWireBytes(const Request& request) const override;
    qint64 replyWireBytes(const Request& request) const override;

private:
    bool m_deduplicates;
    int m_sequence = -1;
    QByteArray m_wire;
    QByteArray m_pending;
};

// One reply the script sends: `bytes` arrive `afterMs` after the request.
struct ScriptedReply {
    qint64 afterMs = 0;
    QByteArray bytes;
};

// A transport whose far end is a function of what was written (and the
// index of the write, from 0). read() advances the virtual clock.
class ScriptedLine : public Transport {
public:
    using Script = std::function<QList<ScriptedReply>(const QByteArray& written, int index)>;

    ScriptedLine(VirtualClock& clock, Script script)
        : m_clock(clock), m_script(std::move(script)) {}

    Status open() override { return success(); }
    void close() override {}
    bool isOpen() const override { return true; }
    Status write(const QByteArray& bytes) override;
    Result<QByteArray> read(int timeoutMs) override;
    void discardInput() override { takeDue(); }
    QString description() const override { return QStringLiteral("the scripted line"); }

    // Every write with the virtual time it happened at.
    struct Write {
        qint64 atMs;
        QByteArray bytes;
    };
    const QList<Write>& writes() const { return m_writes; }
    // Sends bytes at an absolute virtual time (a station nobody asked).
    void schedule(qint64 atMs, const QByteArray& bytes);

private:
    QByteArray takeDue();

    VirtualClock& m_clock;
    Script m_script;
    QList<Write> m_writes;
    QList<std::pair<qint64, QByteArray>> m_pending;  // (due ms, bytes), sorted by time
};

}  // namespace cambench::comm::test
