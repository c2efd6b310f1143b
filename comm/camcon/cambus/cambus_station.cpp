#include "cambus_station.h"

#include <QCoreApplication>

#include <algorithm>

namespace cambench::comm {

namespace {

quint8 ack(int user) {
    return camBusByte(CamBusByteKind::Ack, user);
}
quint8 nak(int user) {
    return camBusByte(CamBusByteKind::Nak, user);
}

const QByteArray kBreak = QByteArray::fromHex("ff0000");

}  // namespace

CamBusStation::CamBusStation(CamBusStationConfig config, qint64 nowMs)
    : m_config(config), m_lastActivity(nowMs) {
    m_config.number = std::clamp(m_config.number, 0, kCamBusLastUser);
    std::fill(std::begin(m_acceptedBit), std::end(m_acceptedBit), -1);
}

qint64 CamBusStation::wireMs(int bytes) const {
    const qint64 baud = std::max(1, m_config.baud);
    return (qint64(bytes) * 10 * 1000 + baud - 1) / baud;
}

QByteArray CamBusStation::takeOutput() {
    QByteArray out;
    out.swap(m_out);
    return out;
}

QList<CamBusStation::Delivery> CamBusStation::takeDeliveries() {
    QList<Delivery> out;
    out.swap(m_deliveries);
    return out;
}

QList<CamBusStation::Received> CamBusStation::takeReceived() {
    QList<Received> out;
    out.swap(m_received);
    return out;
}

quint64 CamBusStation::send(int destination, const QByteArray& data) {
    Outgoing block;
    block.id = m_nextId++;
    block.destination = destination & 0x3F;
    block.data = data;
    m_tx.push_back(block);
    return block.id;
}

void CamBusStation::cancelUnsent(int destination) {
    const bool sending = m_tokenUser == number() && m_phase != Phase::Idle;
    for (auto it = m_tx.begin(); it != m_tx.end();) {
        const bool inTurn = sending && it == m_tx.begin();
        if (it->destination == destination && !it->everSent && !inTurn) {
            it = m_tx.erase(it);
        } else {
            ++it;
        }
    }
}

int CamBusStation::fullQueueAnswers(quint64 id) const {
    for (const Outgoing& block : m_tx)
        if (block.id == id) return block.fullQueueAnswers;
    return 0;
}

bool CamBusStation::cancel(quint64 id) {
    const bool sending = m_tokenUser == number() && m_phase != Phase::Idle;
    for (auto it = m_tx.begin(); it != m_tx.end(); ++it) {
        if (it->id != id) continue;
        if (it->everSent || (sending && it == m_tx.begin())) return false;
        m_tx.erase(it);
        return true;
    }
    return false;
}

void CamBusStation::feed(QByteArrayView encoded, qint64 nowMs) {
    m_pending += encoded.toByteArray();
    const QList<MarkedRead> reads = takeBreakMarked(m_pending);
    for (qsizetype r = 0; r < reads.size(); ++r) {
        const MarkedRead& read = reads.at(r);
        if (read.kind == MarkedRead::Break) {
            hearBreak(nowMs);
            continue;
        }
        if (nowMs < m_deafUntil) continue;
        for (qsizetype i = 0; i < read.data.size(); ++i) {
            // What came with this byte came after it: nobody waits for an
            // answer to it any more (see lateToAnswer()).
            m_lineWentOn = i + 1 < read.data.size() || r + 1 < reads.size();
            hearByte(quint8(read.data.at(i)), nowMs);
        }
    }
    m_lineWentOn = false;
    poll(nowMs);
}

void CamBusStation::write(const QByteArray& bytes, qint64 nowMs) {
    if (m_silent || bytes.isEmpty()) return;
    m_out += escapeBreakMarks(bytes);
    m_lineFreeAt = std::max(m_lineFreeAt, nowMs) + wireMs(int(bytes.size()));
    // No echo on the line (P12): our own bytes move the conversation on as
    // everybody else's do.
    for (char c : bytes) hearByte(quint8(c), nowMs);
}

void CamBusStation::expectWithin(qint64 nowMs, int user) {
    const int ms =
        user >= 0 && m_config.answerMsFor ? m_config.answerMsFor(user) : m_config.answerMs;
    m_awaitedSince = std::max(nowMs, m_lineFreeAt);
    m_awaitedUser = user;
    m_deadline = m_awaitedSince + ms;
}

bool CamBusStation::lateToAnswer() {
    if (!m_lineWentOn) return false;
    ++m_view.lateAnswers;
    return true;
}

void CamBusStation::answered(qint64 nowMs, bool theAnswer) {
    if (!m_answerObserver || m_awaitedUser < 0) return;
    // Another byte instead: the awaited user let its turn go.
    m_answerObserver(m_awaitedUser,
                     theAnswer ? std::max<qint64>(0, nowMs - m_awaitedSince) : qint64(-1));
}

void CamBusStation::answerMissed() {
    if (m_answerObserver && m_awaitedUser >= 0) m_answerObserver(m_awaitedUser, -1);
}

void CamBusStation::hearByte(quint8 byte, qint64 nowMs) {
    const int user = camBusUser(byte);
    const CamBusByteKind kind = camBusKind(byte);
    const auto restart = [&] {
        m_phase = Phase::Idle;
        hearByte(byte, nowMs);
    };
    switch (m_phase) {
        case Phase::Idle:
            if (byte == kCamBusToken1) {
                m_phase = Phase::Token1;
            } else if (kind == CamBusByteKind::Rid) {
                ridHeard(user, nowMs);
            }
            return;
        case Phase::Token1:
            if (byte == kCamBusToken2) {
                m_phase = Phase::Token2;
            } else {
                restart();
            }
            return;
        case Phase::Token2:
            if (kind == CamBusByteKind::Did) {
                m_tokenUser = user;
                m_phase = Phase::Token3;
            } else {
                restart();
            }
            return;
        case Phase::Token3:
            if (byte == camBusByte(CamBusByteKind::Did, m_tokenUser)) {
                tokenHeard(m_tokenUser, nowMs);
            } else {
                restart();
            }
            return;
        case Phase::TxAnswer:
            m_view.users[m_tokenUser].answers = true;
            answered(nowMs, byte == ack(m_tokenUser) || byte == nak(m_tokenUser));
            if (byte == ack(m_tokenUser)) {
                m_phase = Phase::To;
                expectWithin(nowMs, m_tokenUser);
            } else if (byte == nak(m_tokenUser)) {
                endTurn(nowMs);
            } else {
                endTurn(nowMs);
                hearByte(byte, nowMs);
            }
            return;
        case Phase::To:
            if (kind != CamBusByteKind::Did) {
                endTurn(nowMs);
                hearByte(byte, nowMs);
                return;
            }
            m_destination = user;
            m_phase = Phase::RxAnswer;
            expectWithin(nowMs, m_destination);
            if (user == number() && !m_silent && !lateToAnswer())
                writeByte((!m_room || m_room()) ? ack(user) : nak(user), nowMs);
            return;
        case Phase::RxAnswer:
            answered(nowMs, byte == ack(m_destination) || byte == nak(m_destination));
            if (byte == ack(m_destination)) {
                m_phase = Phase::Block;
                m_block.clear();
                expectWithin(nowMs, m_tokenUser);
                if (m_tokenUser == number() && !m_tx.empty()) {
                    // Too late for the block: the turn has passed; it goes
                    // at our next token (it did not leave).
                    if (lateToAnswer()) {
                        endTurn(nowMs);
                        return;
                    }
                    Outgoing& head = m_tx.front();
                    const Result<QByteArray> wire =
                        encodeCamBusBlock({head.data, m_sendBit[head.destination]});
                    head.everSent = true;
                    if (wire) write(*wire, nowMs);
                }
            } else if (byte == nak(m_destination)) {
                // A full queue is no failure: another destination may go first.
                if (m_tokenUser == number() && !m_tx.empty()) {
                    ++m_tx.front().fullQueueAnswers;
                    m_tx.push_back(m_tx.front());
                    m_tx.pop_front();
                }
                endTurn(nowMs);
            } else {
                // Another user's byte instead of the answer to our TO: the
                // others had gone on, our TO came too late. The turn was
                // ours to lose, not the destination's silence (P9): the
                // block goes at our next token (CB8).
                if (m_tokenUser == number()) ++m_view.lateAnswers;
                endTurn(nowMs);
                hearByte(byte, nowMs);
            }
            return;
        case Phase::Block:
            if (m_block.isEmpty()) answered(nowMs, true);
            m_block += char(byte);
            expectWithin(nowMs, m_tokenUser);
            if (quint8(m_block.at(0)) == 0) {
                endTurn(nowMs);
            } else if (m_block.size() == quint8(m_block.at(0)) + 3) {
                blockHeard(nowMs);
            }
            return;
        case Phase::BlockAck:
            answered(nowMs, byte == nak(m_destination));
            if (byte == nak(m_destination)) {
                if (m_tokenUser == number() && !m_tx.empty())
                    finishHead(Delivery::Delivered, QString());
                endTurn(nowMs);
            } else {
                if (m_tokenUser == number())
                    senderTurnFailed(QCoreApplication::translate(
                                         "cambench::comm", "user %1 did not acknowledge the block")
                                         .arg(m_destination));
                endTurn(nowMs);
                hearByte(byte, nowMs);
            }
            return;
        case Phase::RidAnswer:
            if (byte == ack(m_ridUser)) {
                userFound(m_ridUser);
                endTurn(nowMs);
            } else {
                ridUnanswered();
                endTurn(nowMs);
                hearByte(byte, nowMs);
            }
            return;
    }
}

void CamBusStation::hearBreak(qint64 nowMs) {
    // Every break: the transfer in progress is dropped, block bits are
    // forgotten (P8), mastership ends, the table is searched again.
    if (!m_init) ++m_view.initPhases;
    m_init = true;
    m_view.inInitPhase = true;
    m_view.users.clear();
    m_view.tokenHolder = -1;
    m_view.master = -1;
    m_phase = Phase::Idle;
    m_deadline = -1;
    m_block.clear();
    m_master = false;
    m_masterNextAt = -1;
    m_table.clear();
    m_roundUsers.clear();
    m_roundWithoutUs = false;
    std::fill(std::begin(m_sendBit), std::end(m_sendBit), false);
    std::fill(std::begin(m_acceptedBit), std::end(m_acceptedBit), -1);
    // A block that left but was not acknowledged may have been taken: it
    // is not sent again under a fresh block bit, which would execute it twice.
    while (!m_tx.empty() && m_tx.front().everSent)
        finishHead(Delivery::Uncertain,
                   QCoreApplication::translate("cambench::comm",
                                               "an initialisation phase began before user %1 "
                                               "acknowledged the block")
                       .arg(m_tx.front().destination));
    for (Outgoing& block : m_tx) block.silentTurns = 0;
    const qint64 lastBreak = std::max(nowMs, m_lineFreeAt);
    m_lastActivity = lastBreak;
    m_masterWaitEnd =
        lastBreak + m_config.breakWaitMs + qint64(number()) * std::max(0, m_config.tickMs);
}

void CamBusStation::ridHeard(int user, qint64 nowMs) {
    m_lastActivity = nowMs;
    m_masterWaitEnd = -1;  // somebody is master
    if (!m_init) {
        // An RID without the breaks (we opened during a search).
        m_init = true;
        m_view.inInitPhase = true;
    }
    m_ridUser = user;
    m_phase = Phase::RidAnswer;
    expectWithin(nowMs, user);
    if (user == number() && !m_silent && !lateToAnswer()) {
        m_joined = true;
        writeByte(ack(user), nowMs);
    }
}

void CamBusStation::userFound(int user) {
    const bool known = m_view.users.contains(user);
    m_view.users[user];
    if (m_view.master < 0 || user < m_view.master) m_view.master = user;
    if (!m_master) return;
    if (known) {
        ++m_ridRun;
        return;
    }
    m_table.insert(std::upper_bound(m_table.begin(), m_table.end(), user), user);
    m_ridRun = 0;
}

void CamBusStation::ridUnanswered() {
    if (m_master) ++m_ridRun;
}

void CamBusStation::tokenHeard(int user, qint64 nowMs) {
    if (m_init) {
        m_init = false;  // the first token ends the initialisation phase for all
        m_view.inInitPhase = false;
    }
    ++m_view.tokens;
    m_view.tokenHolder = user;
    m_view.users[user].lastTokenMs = nowMs;
    // CB1: a whole round of tokens without us: we are not in the table.
    if (m_roundUsers.contains(user)) {
        m_roundWithoutUs = !m_roundUsers.contains(number());
        m_roundUsers.clear();
    }
    m_roundUsers.insert(user);
    m_tokenUser = user;
    m_destination = -1;
    m_phase = Phase::TxAnswer;
    expectWithin(nowMs, m_tokenUser);
    if (user != number()) return;
    m_lastActivity = nowMs;
    m_joinTries = 0;  // in the table
    if (m_silent || lateToAnswer()) return;
    if (m_config.joinBeforeFirstBlock && !m_joined && !m_tx.empty()) m_wantsBreakIn = true;
    if (maySend()) {
        QByteArray answer;
        answer += char(ack(user));
        answer += char(camBusByte(CamBusByteKind::Did, m_tx.front().destination));
        write(answer, nowMs);
    } else {
        writeByte(nak(user), nowMs);
    }
}

bool CamBusStation::maySend() const {
    return !m_tx.empty() && !m_silent && (!m_config.joinBeforeFirstBlock || m_joined);
}

void CamBusStation::blockHeard(qint64 nowMs) {
    const int source = m_tokenUser;
    ++m_view.users[source].blocks;
    QByteArray bytes = m_block;
    m_block.clear();
    m_phase = Phase::BlockAck;
    expectWithin(nowMs, m_destination);
    if (m_destination != number() || m_silent) return;
    const Result<std::optional<CamBusBlock>> block = takeCamBusBlock(bytes);
    if (!block || !block->has_value()) return;  // a bad checksum gets silence (P5)
    const int bit = (*block)->blockBit ? 1 : 0;
    if (m_acceptedBit[source] != bit) {
        m_acceptedBit[source] = bit;
        m_received << Received{source, (*block)->data};
    }
    // A repeat (its acknowledgement was lost) is acknowledged, not taken
    // again. Heard too late to acknowledge, the block is taken all the same:
    // its sender repeats it at its next token, and the repeat is
    // acknowledged.
    if (!lateToAnswer()) writeByte(nak(number()), nowMs);
}

void CamBusStation::endTurn(qint64 nowMs) {
    m_phase = Phase::Idle;
    m_deadline = -1;
    m_block.clear();
    if (m_master)
        m_masterNextAt = std::max(nowMs, m_lineFreeAt) + std::max(0, m_config.masterGapMs);
}

void CamBusStation::turnTimedOut(qint64 nowMs) {
    if (m_phase != Phase::RidAnswer) answerMissed();
    switch (m_phase) {
        case Phase::TxAnswer:
            m_view.users[m_tokenUser].answers = false;
            break;
        case Phase::RxAnswer:
        case Phase::Block:
        case Phase::BlockAck:
            if (m_tokenUser == number())
                senderTurnFailed(
                    m_phase == Phase::RxAnswer
                        ? QCoreApplication::translate("cambench::comm",
                                                      "user %1 did not answer its TO")
                              .arg(m_destination)
                        : QCoreApplication::translate("cambench::comm",
                                                      "user %1 did not acknowledge the block")
                              .arg(m_destination));
            break;
        case Phase::RidAnswer:
            ridUnanswered();
            break;
        default:
            break;
    }
    endTurn(nowMs);
}

void CamBusStation::senderTurnFailed(const QString& problem) {
    if (m_tx.empty()) return;
    Outgoing& head = m_tx.front();
    if (++head.silentTurns < m_config.maxSilentTurns) return;
    // P9: dropped after 3 silent turns; the bit toggles if the block ever
    // left, so that a later block is not taken for its repeat.
    const bool sent = head.everSent;
    if (sent) m_sendBit[head.destination] = !m_sendBit[head.destination];
    m_deliveries << Delivery{head.id, head.destination,
                             sent ? Delivery::Uncertain : Delivery::NotTaken, problem};
    m_tx.pop_front();
}

void CamBusStation::finishHead(Delivery::Result result, const QString& problem) {
    const Outgoing head = m_tx.front();
    m_tx.pop_front();
    if (result == Delivery::Delivered) m_sendBit[head.destination] = !m_sendBit[head.destination];
    m_deliveries << Delivery{head.id, head.destination, result, problem};
}

void CamBusStation::breakIn(qint64 nowMs) {
    if (m_config.joinBeforeFirstBlock) ++m_joinTries;
    m_wantsBreakIn = false;
    m_roundWithoutUs = false;
    if (m_silent) return;
    const qint64 start = std::max(nowMs, m_lineFreeAt);
    QByteArray breaks;
    for (int i = 0; i < m_config.breaks; ++i) breaks += kBreak;
    m_out += breaks;
    // A break: the line at 0 for 2 character times, idle for 2 (docs/protocols/cambus.md).
    m_lineFreeAt = start + wireMs(4 * m_config.breaks);
    // While our breaks hold the line, what others sent is lost in them.
    m_deafUntil = m_lineFreeAt;
    hearBreak(nowMs);
}

void CamBusStation::becomeMaster(qint64 nowMs) {
    m_master = true;
    m_table.clear();
    m_ridUser = -1;
    m_ridRun = 0;
    m_nextIndex = 0;
    m_masterNextAt = nowMs;
}

void CamBusStation::masterNext(qint64 nowMs) {
    if (m_init) {
        if (m_ridRun < m_config.ridRunWithoutNew || m_table.isEmpty()) {
            writeByte(camBusByte(CamBusByteKind::Rid, (m_ridUser + 1) & 0x3F), nowMs);
            return;
        }
        m_nextIndex = 0;
    }
    if (m_table.isEmpty()) return;
    const int user = m_table.at(m_nextIndex % m_table.size());
    m_nextIndex = (m_nextIndex + 1) % m_table.size();
    write(camBusToken(user), nowMs);
}

void CamBusStation::poll(qint64 nowMs) {
    if (m_deadline >= 0 && nowMs >= m_deadline) turnTimedOut(nowMs);
    if (m_masterWaitEnd >= 0 && nowMs >= m_masterWaitEnd) {
        m_masterWaitEnd = -1;
        if (m_config.startsInitPhases && !m_silent) becomeMaster(nowMs);
    }
    if (m_master && m_phase == Phase::Idle && m_masterNextAt >= 0 && nowMs >= m_masterNextAt) {
        m_masterNextAt = -1;
        masterNext(nowMs);
    }
    if (m_silent || m_phase != Phase::Idle || gaveUpJoining()) return;
    const bool joining = m_config.joinBeforeFirstBlock && !m_joined && !m_tx.empty();
    if (joining && (m_wantsBreakIn || m_roundWithoutUs)) {
        breakIn(nowMs);
        return;
    }
    if (m_config.startsInitPhases && !m_master && m_masterWaitEnd < 0 &&
        nowMs - m_lastActivity >= m_config.silenceMs)
        breakIn(nowMs);
}

qint64 CamBusStation::nextTimerMs() const {
    qint64 next = -1;
    const auto consider = [&next](qint64 at) {
        if (at >= 0 && (next < 0 || at < next)) next = at;
    };
    consider(m_deadline);
    consider(m_masterWaitEnd);
    // The rest acts only between turns; a turn ends by its deadline.
    if (m_phase != Phase::Idle || m_silent || gaveUpJoining()) return next;
    if (m_master) consider(m_masterNextAt);
    if (m_config.startsInitPhases && !m_master && m_masterWaitEnd < 0)
        consider(m_lastActivity + m_config.silenceMs);
    const bool joining = m_config.joinBeforeFirstBlock && !m_joined && !m_tx.empty();
    if (joining && (m_wantsBreakIn || m_roundWithoutUs)) consider(0);
    return next;
}

}  // namespace cambench::comm
