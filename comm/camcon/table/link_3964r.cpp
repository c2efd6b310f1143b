#include "link_3964r.h"

#include "frame_3964r.h"

#include <QCoreApplication>

#include <algorithm>

namespace cambench::comm::table {

namespace {

// "DLE", "NAK", ... or "0x41": for log lines about single bytes.
QString byteName(char c) {
    switch (c) {
        case kStx:
            return QStringLiteral("STX");
        case kEtx:
            return QStringLiteral("ETX");
        case kDle:
            return QStringLiteral("DLE");
        case kNak:
            return QStringLiteral("NAK");
        default:
            return QStringLiteral("0x") +
                   QString::number(quint8(c), 16).toUpper().rightJustified(2, QLatin1Char('0'));
    }
}

}  // namespace

Link3964R::Link3964R(Priority priority, Timing timing) : m_priority(priority), m_timing(timing) {
    // A zero delay would make a deadline expire in the call that set it.
    m_timing.ackTimeoutMs = std::max(1, m_timing.ackTimeoutMs);
    m_timing.charTimeoutMs = std::max(1, m_timing.charTimeoutMs);
    m_timing.attempts = std::max(1, m_timing.attempts);
}

Actions Link3964R::send(const QByteArray& telegram, qint64 nowMs, Repeat repeat) {
    // No poll() here: an expiring transfer must not report its end in the
    // Actions of this call, which concern only `telegram`. A deadline already
    // past is handled by the next feed() or poll().
    Actions actions;
    if (m_telegram) {
        actions.sendFailed = QCoreApplication::translate(
            "cambench::comm",
            "3964R: a telegram is still being sent; wait for its end before sending the next one.");
        return actions;
    }
    if (telegram.isEmpty() || telegram.size() > kMaxTelegramBytes) {
        actions.sendFailed =
            QCoreApplication::translate(
                "cambench::comm",
                "3964R: a telegram of %1 bytes cannot be sent (1..%2 bytes allowed).")
                .arg(telegram.size())
                .arg(kMaxTelegramBytes);
        return actions;
    }
    m_telegram = telegram;
    m_attempt = 0;
    m_repeat = repeat;
    if (m_state == State::Idle) {
        startAttempt(nowMs, actions);
    } else {
        actions.log.append(QStringLiteral("telegram of %1 bytes queued until the incoming one ends")
                               .arg(telegram.size()));
    }
    return actions;
}

Actions Link3964R::feed(QByteArrayView bytes, qint64 nowMs) {
    Actions actions = poll(nowMs);
    for (char c : bytes) handleByte(c, nowMs, actions);
    return actions;
}

Actions Link3964R::poll(qint64 nowMs) {
    Actions actions;
    if (m_deadlineMs >= 0 && nowMs >= m_deadlineMs) handleTimeout(nowMs, actions);
    return actions;
}

void Link3964R::reset() {
    m_state = State::Idle;
    m_deadlineMs = -1;
    m_telegram.reset();
    m_attempt = 0;
    m_buffer.clear();
    m_bcc = 0;
    m_dlePending = false;
    m_drainReason.clear();
}

void Link3964R::enter(State state, qint64 deadlineMs) {
    m_state = state;
    m_deadlineMs = deadlineMs;
}

void Link3964R::handleByte(char c, qint64 nowMs, Actions& actions) {
    switch (m_state) {
        case State::Idle:
        case State::RetryPause:
            if (c == kStx) {
                startReceive(nowMs, actions);
            } else {
                // Typically a late DLE or NAK of an attempt already given up.
                actions.log.append(
                    QStringLiteral("ignored %1 outside a transfer").arg(byteName(c)));
            }
            break;
        case State::SendWaitDle:
            onSendWaitDle(c, nowMs, actions);
            break;
        case State::SendWaitAck:
            onSendWaitAck(c, nowMs, actions);
            break;
        case State::Receive:
            onReceive(c, nowMs, actions);
            break;
        case State::ReceiveBcc:
            onReceiveBcc(c, nowMs, actions);
            break;
        case State::Drain:
            m_deadlineMs = nowMs + m_timing.charTimeoutMs;  // wait for a quiet line
            break;
    }
}

void Link3964R::handleTimeout(qint64 nowMs, Actions& actions) {
    switch (m_state) {
        case State::Idle:
            m_deadlineMs = -1;
            break;
        case State::SendWaitDle:
            failAttempt(
                QCoreApplication::translate("cambench::comm", "no DLE within %1 ms after STX")
                    .arg(m_timing.ackTimeoutMs),
                nowMs, actions);
            break;
        case State::SendWaitAck:
            failAttempt(
                QCoreApplication::translate("cambench::comm", "no DLE within %1 ms after the block")
                    .arg(m_timing.ackTimeoutMs),
                nowMs, actions, true);
            break;
        case State::RetryPause:
            startAttempt(nowMs, actions);
            break;
        case State::Receive:
        case State::ReceiveBcc:
            // The line is already quiet: answer at once.
            actions.write.append(kNak);
            actions.log.append(
                QStringLiteral("NAK: character delay over %1 ms after %2 telegram bytes")
                    .arg(m_timing.charTimeoutMs)
                    .arg(m_buffer.size()));
            finishReceive(nowMs, actions);
            break;
        case State::Drain:
            actions.write.append(kNak);
            actions.log.append(QStringLiteral("NAK: %1").arg(m_drainReason));
            finishReceive(nowMs, actions);
            break;
    }
}

void Link3964R::onSendWaitDle(char c, qint64 nowMs, Actions& actions) {
    if (c == kDle) {
        actions.write.append(encodeBlock3964r(*m_telegram));
        actions.log.append(QStringLiteral("DLE received; block of %1 telegram bytes sent")
                               .arg(m_telegram->size()));
        enter(State::SendWaitAck, nowMs + m_timing.ackTimeoutMs);
        return;
    }
    if (c == kStx) {
        if (m_priority == Priority::High) {
            // The partner has low priority and will yield with a DLE.
            actions.log.append(
                QStringLiteral("STX from the partner while waiting for DLE: kept priority"));
            return;
        }
        // Yielding is no failed attempt: the same attempt runs again afterwards.
        --m_attempt;
        actions.log.append(QStringLiteral(
            "STX from the partner while waiting for DLE: yielded (low priority), receiving first"));
        startReceive(nowMs, actions);
        return;
    }
    failAttempt(QCoreApplication::translate("cambench::comm", "%1 instead of DLE after STX")
                    .arg(byteName(c)),
                nowMs, actions);
}

void Link3964R::onSendWaitAck(char c, qint64 nowMs, Actions& actions) {
    if (c == kDle) {
        actions.sendDone = true;
        actions.log.append(QStringLiteral("DLE: telegram acknowledged (attempt %1 of %2)")
                               .arg(m_attempt)
                               .arg(m_timing.attempts));
        m_telegram.reset();
        m_attempt = 0;
        enter(State::Idle, -1);
        return;
    }
    if (c == kNak) {
        failAttempt(QCoreApplication::translate("cambench::comm",
                                                "NAK after the block (the partner found it bad)"),
                    nowMs, actions);
        return;
    }
    if (c == kStx) {
        // The partner took no notice of the block and starts its own
        // transfer: this attempt failed, but its telegram is taken first so
        // that neither side waits for the other.
        failAttempt(
            QCoreApplication::translate("cambench::comm", "STX instead of DLE after the block"),
            nowMs, actions, true);
        startReceive(nowMs, actions);
        return;
    }
    failAttempt(QCoreApplication::translate("cambench::comm", "%1 instead of DLE after the block")
                    .arg(byteName(c)),
                nowMs, actions, true);
}

void Link3964R::onReceive(char c, qint64 nowMs, Actions& actions) {
    m_bcc ^= quint8(c);
    m_deadlineMs = nowMs + m_timing.charTimeoutMs;
    if (m_dlePending) {
        m_dlePending = false;
        if (c == kEtx) {
            m_state = State::ReceiveBcc;
            return;
        }
        if (c != kDle) {
            startDrain(QStringLiteral("DLE followed by %1 inside the block").arg(byteName(c)),
                       nowMs, actions);
            return;
        }
    } else if (c == kDle) {
        m_dlePending = true;
        return;
    }
    if (m_buffer.size() >= kMaxTelegramBytes) {
        startDrain(QStringLiteral("telegram longer than %1 bytes").arg(kMaxTelegramBytes), nowMs,
                   actions);
        return;
    }
    m_buffer.append(c);
}

void Link3964R::onReceiveBcc(char c, qint64 nowMs, Actions& actions) {
    if (quint8(c) != m_bcc) {
        actions.write.append(kNak);
        actions.log.append(
            QStringLiteral("NAK: BCC %1 received, %2 computed over %3 telegram bytes")
                .arg(byteName(c), byteName(char(m_bcc)))
                .arg(m_buffer.size()));
        finishReceive(nowMs, actions);
        return;
    }
    actions.write.append(kDle);
    actions.received.append(m_buffer);
    actions.log.append(
        QStringLiteral("telegram of %1 bytes received, DLE sent").arg(m_buffer.size()));
    finishReceive(nowMs, actions);
}

void Link3964R::startAttempt(qint64 nowMs, Actions& actions) {
    ++m_attempt;
    actions.write.append(kStx);
    actions.log.append(QStringLiteral("STX (attempt %1 of %2, telegram of %3 bytes)")
                           .arg(m_attempt)
                           .arg(m_timing.attempts)
                           .arg(m_telegram->size()));
    enter(State::SendWaitDle, nowMs + m_timing.ackTimeoutMs);
}

void Link3964R::failAttempt(const QString& reason, qint64 nowMs, Actions& actions, bool maybeRead) {
    actions.log.append(QStringLiteral("attempt %1 of %2 failed: %3")
                           .arg(m_attempt)
                           .arg(m_timing.attempts)
                           .arg(reason));
    if (maybeRead && m_repeat == Repeat::OnlyUnread) {
        actions.sendFailed =
            QCoreApplication::translate(
                "cambench::comm",
                "3964R: %1; the device may have executed the telegram, which must not be sent "
                "twice. Read back what it changes before trying again.")
                .arg(reason);
        m_telegram.reset();
        m_attempt = 0;
        enter(State::Idle, -1);
        return;
    }
    if (m_attempt < m_timing.attempts) {
        enter(State::RetryPause, nowMs + m_timing.charTimeoutMs);
        return;
    }
    actions.sendFailed =
        QCoreApplication::translate(
            "cambench::comm",
            "3964R: the partner did not acknowledge the telegram in %1 attempts (last: %2). Check "
            "the cable and that the device's serial mode is 3964R with the same baud rate and "
            "parity (n96: 9600 8N1, e38: 38400 8E1).")
            .arg(m_timing.attempts)
            .arg(reason);
    m_telegram.reset();
    m_attempt = 0;
    enter(State::Idle, -1);
}

void Link3964R::startReceive(qint64 nowMs, Actions& actions) {
    actions.write.append(kDle);
    m_buffer.clear();
    m_bcc = 0;
    m_dlePending = false;
    enter(State::Receive, nowMs + m_timing.charTimeoutMs);
}

void Link3964R::startDrain(const QString& reason, qint64 nowMs, Actions& actions) {
    actions.log.append(QStringLiteral("bad block (%1): waiting for a quiet line").arg(reason));
    m_drainReason = reason;
    m_buffer.clear();
    m_dlePending = false;
    enter(State::Drain, nowMs + m_timing.charTimeoutMs);
}

void Link3964R::finishReceive(qint64 nowMs, Actions& actions) {
    m_buffer.clear();
    m_bcc = 0;
    m_dlePending = false;
    m_drainReason.clear();
    // A queued, yielded or failed-but-not-exhausted telegram goes next.
    if (m_telegram) {
        startAttempt(nowMs, actions);
    } else {
        enter(State::Idle, -1);
    }
}

}  // namespace cambench::comm::table
