#pragma once

#include <QByteArray>
#include <QByteArrayView>
#include <QList>
#include <QString>

#include <optional>

namespace cambench::comm::table {

// What the link wants done after one call: bytes to put on the line, the
// telegrams that arrived complete, the end of the caller's transfer, and
// lines for a traffic log. The caller owns the port and the clock.
struct Actions {
    QByteArray write;
    QList<QByteArray> received;         // complete incoming telegrams (DLE already undoubled)
    bool sendDone = false;              // the partner acknowledged the telegram of send()
    std::optional<QString> sendFailed;  // the telegram of send() was given up: why, what to do
    QList<QString> log;
};

// The times of 3964R (notes 7). Outside Link3964R because a nested struct
// with member initialisers cannot be a default argument of its own class.
struct Timing3964R {
    int ackTimeoutMs = 2000;  // acknowledgement delay (QVZ)
    int charTimeoutMs = 220;  // character delay (ZVZ); also the pause before a retry
    int attempts = 6;         // attempts per telegram, the first one included
};

// The 3964R procedure (notes 7) as a state machine driven by bytes and by
// time: no port, no timer, no thread. The caller passes every byte read with
// feed(), calls poll() at nextDeadlineMs(), writes Actions::write, and gives
// every call the current time of one monotonic clock, so tests run on a fake
// one.
//
// Sending: STX, wait for DLE, the block (encodeBlock3964r), wait for DLE.
// NAK, any other answer or no answer within ackTimeoutMs fails the attempt;
// after a quiet pause of charTimeoutMs (so that a late answer to the old
// attempt is not taken for one to the new) the next attempt starts, up to
// `attempts` in all.
//
// Receiving is possible whenever no own transfer is past its STX: the
// device's reply arrives as its own transfer, which the PC acknowledges with
// DLE. The receiver answers DLE to a good block and NAK to a bad BCC, a
// character gap over charTimeoutMs, a DLE followed by anything but DLE or
// ETX, or a telegram over kMaxTelegramBytes; after the last three it first
// waits until the line has been quiet for charTimeoutMs, so that the rest of
// the block is not read as a new start.
//
// Initialisation conflict (both sides send STX at once): the low-priority
// side yields, answers DLE, receives, and then sends its own telegram; the
// high-priority side (the PC) keeps waiting for its DLE.
class Link3964R {
public:
    enum class Priority { High, Low };  // PC = High, device (simulator) = Low

    using Timing = Timing3964R;

    // The longest telegram either side accepts (without the doubled DLEs).
    // An RK512 telegram is at most 10 + 128 bytes, a short command 64; the
    // margin keeps odd firmware working while bounding memory.
    static constexpr int kMaxTelegramBytes = 600;

    explicit Link3964R(Priority priority, Timing timing = {});

    // Starts a transfer of `telegram` (the bytes between STX and DLE ETX,
    // undoubled), or queues it while a telegram is being received. One at a
    // time: while sending() a further call is refused (its Actions carry
    // sendFailed) and the running transfer goes on. The Actions of send()
    // concern only `telegram`; it handles no deadline.
    //
    // `repeat` says whether an attempt whose block may have reached the
    // partner (no DLE, or another byte, after the block) may be repeated:
    // the partner may have executed the telegram and only its DLE was lost.
    // With Repeat::OnlyUnread such an attempt ends the transfer (sendFailed
    // says the telegram may have been executed); failures before the block,
    // and a NAK after it, are repeated as always.
    enum class Repeat { Always, OnlyUnread };
    Actions send(const QByteArray& telegram, qint64 nowMs, Repeat repeat = Repeat::Always);
    // Bytes read from the line. Handles an expired deadline first.
    Actions feed(QByteArrayView bytes, qint64 nowMs);
    // Handles an expired deadline; does nothing before nextDeadlineMs().
    Actions poll(qint64 nowMs);

    // When poll() has something to do; -1 = nothing to wait for.
    qint64 nextDeadlineMs() const { return m_deadlineMs; }
    // Nothing sent, received or waited for.
    bool idle() const { return m_state == State::Idle && !m_telegram; }
    // A telegram of send() is queued or under way.
    bool sending() const { return m_telegram.has_value(); }
    // Telegram bytes held for a block being received (bounded by kMaxTelegramBytes).
    int bufferedBytes() const { return int(m_buffer.size()); }
    Priority priority() const { return m_priority; }
    // Drops every transfer without a word to the partner (port closed or reopened).
    void reset();

private:
    enum class State {
        Idle,
        SendWaitDle,  // STX sent, waiting for the partner's DLE
        SendWaitAck,  // block sent, waiting for DLE (or NAK)
        RetryPause,   // an attempt failed; quiet pause before the next STX
        Receive,      // DLE sent after the partner's STX; reading its block
        ReceiveBcc,   // DLE ETX read; the next byte is the BCC
        Drain,        // the block is bad; waiting for a quiet line before NAK
    };

    void handleByte(char c, qint64 nowMs, Actions& actions);
    void handleTimeout(qint64 nowMs, Actions& actions);
    void onSendWaitDle(char c, qint64 nowMs, Actions& actions);
    void onSendWaitAck(char c, qint64 nowMs, Actions& actions);
    void onReceive(char c, qint64 nowMs, Actions& actions);
    void onReceiveBcc(char c, qint64 nowMs, Actions& actions);

    void startAttempt(qint64 nowMs, Actions& actions);
    // `maybeRead`: the partner may have taken the block (see Repeat).
    void failAttempt(const QString& reason, qint64 nowMs, Actions& actions, bool maybeRead = false);
    void startReceive(qint64 nowMs, Actions& actions);
    void startDrain(const QString& reason, qint64 nowMs, Actions& actions);
    void finishReceive(qint64 nowMs, Actions& actions);
    void enter(State state, qint64 deadlineMs);

    Priority m_priority;
    Timing m_timing;
    State m_state = State::Idle;
    qint64 m_deadlineMs = -1;

    std::optional<QByteArray> m_telegram;  // the telegram of send() until done or given up
    int m_attempt = 0;                     // attempts started for m_telegram
    Repeat m_repeat = Repeat::Always;      // of m_telegram

    QByteArray m_buffer;        // undoubled data of the block being received
    quint8 m_bcc = 0;           // XOR of the block's bytes as read so far
    bool m_dlePending = false;  // the last data byte read was a single DLE
    QString m_drainReason;      // why the block in Drain will be answered NAK
};

}  // namespace cambench::comm::table
