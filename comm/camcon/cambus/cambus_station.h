#pragma once

#include "cambus_block.h"
#include "cambus_view.h"

#include <QByteArray>
#include <QList>
#include <QSet>

#include <deque>
#include <functional>

namespace cambench::comm {

// How one user behaves on the bus (docs/protocols/cambus.md and its P-lines).
struct CamBusStationConfig {
    int number = kCamBusDefaultPcNumber;  // 0..63
    int baud = 38400;
    int answerMs = 10;  // T (P11): every answer, every gap inside a sender's bytes
    // Set: T for an answer or gap of this user instead (the simulator gives
    // the PC beyond its pseudo-terminal more time on a loaded machine).
    std::function<int(int user)> answerMsFor;
    int silenceMs = 1250;        // not polled this long: start an initialisation phase
    int breakWaitMs = 60;        // after the last break, plus number x tickMs (P2)
    int tickMs = 1;              // P2
    int breaks = 64;             // breaks that start an initialisation phase
    int ridRunWithoutNew = 130;  // P3: RIDs in a row without a new user end the search
    int maxSilentTurns = 3;      // P9
    int masterGapMs = 0;         // P1: the master's pause before the next token (0: none)
    // The PC's rule (docs/protocols/cambus.md, "The PC"): no block before this run answered its own
    // RID, so that no block bit left from an earlier run swallows the first block; it breaks in (an
    // initialisation phase) when polled before, or when a whole token round went by without it (see
    // README, CB1).
    bool joinBeforeFirstBlock = false;
    // Takes part in starting initialisation phases when not polled. A
    // user that falls silent (simulator fault) does not.
    bool startsInitPhases = true;
};

// One user of a Cam-BUS: follows every byte on the line, answers its DID,
// TO and RID, sends its blocks when it holds the token, takes blocks
// addressed to it (with the block bit's repeat check) and, when it wins an
// initialisation phase, is the master that searches the users and passes
// the token. Fed with the bytes heard and with time; never touches a line:
// the PC's framing backend and each simulated user run the same machine.
// Its own bytes count as heard (the line has no echo, P12).
class CamBusStation {
public:
    CamBusStation(CamBusStationConfig config, qint64 nowMs);

    const CamBusStationConfig& config() const { return m_config; }
    int number() const { return m_config.number; }

    // Bytes from the line in P12's encoding (FF 00 00 = a break).
    void feed(QByteArrayView encoded, qint64 nowMs);
    void poll(qint64 nowMs);
    qint64 nextTimerMs() const;
    // What this user writes, in P12's encoding, since the last call.
    QByteArray takeOutput();

    // Sending: one block to `destination`, sent at a later token of ours.
    quint64 send(int destination, const QByteArray& data);
    // Drops blocks to `destination` that have not started to leave.
    void cancelUnsent(int destination);
    // Drops block `id` unless it has started to leave; false when it has
    // (its outcome will come as a Delivery) or is not queued.
    bool cancel(quint64 id);
    // How often the destination answered block `id`'s TO with a full
    // receive queue (80+D): no failure, but worth saying when it goes on.
    int fullQueueAnswers(quint64 id) const;
    bool hasQueued() const { return !m_tx.empty(); }
    struct Delivery {
        quint64 id = 0;
        int destination = 0;
        enum Result { Delivered, NotTaken, Uncertain } result = Delivered;
        QString problem;  // NotTaken, Uncertain: what happened
    };
    QList<Delivery> takeDeliveries();

    // Told of every answer this user waited for (to a DID, to a TO, the
    // first byte of a block after the room answer, an acknowledgement): who
    // owed it and how long after the byte it answers it came, or -1 when
    // none came within T (or a block stopped for longer) and the turn
    // ended. The simulator measures the PC's answers with it.
    using AnswerObserver = std::function<void(int user, qint64 ms)>;
    void setAnswerObserver(AnswerObserver observer) { m_answerObserver = std::move(observer); }

    // Receiving: whether the receive queue has room (P10; default: always).
    void setRoomCheck(std::function<bool()> room) { m_room = std::move(room); }
    struct Received {
        int source = 0;
        QByteArray data;
    };
    QList<Received> takeReceived();

    // Starts an initialisation phase now (tests; a second init phase).
    void breakIn(qint64 nowMs);
    // A silent user answers nothing and sends nothing (simulator fault).
    void setSilent(bool silent) { m_silent = silent; }

    // The PC broke in this many times in a row without getting the token
    // since: it stops disturbing the bus (its answers may come too late).
    static constexpr int kMaxJoinTries = 3;
    bool gaveUpJoining() const {
        return m_config.joinBeforeFirstBlock && m_joinTries >= kMaxJoinTries;
    }
    // A new request may try again.
    void resetJoinTries() { m_joinTries = 0; }

    bool isMaster() const { return m_master; }
    // Answered its own RID since the start (or was polled after that).
    bool joined() const { return m_joined; }
    const CamBusView& view() const { return m_view; }

private:
    enum class Phase {
        Idle,       // between turns: a token, an RID or a break may come
        Token1,     // A5 heard
        Token2,     // A5 37 heard
        Token3,     // A5 37 S heard
        TxAnswer,   // token to S: S answers 40+S (a block) or 80+S (none)
        To,         // S has a block: its TO follows
        RxAnswer,   // D answers 40+D (room) or 80+D (full)
        Block,      // LEN data CHK1 CHK2 from S
        BlockAck,   // D acknowledges with 80+D
        RidAnswer,  // the master searched user s: 40+s or silence
    };
    struct Outgoing {
        quint64 id = 0;
        int destination = 0;
        QByteArray data;
        bool everSent = false;  // its bytes went out at least once
        int silentTurns = 0;
        int fullQueueAnswers = 0;
    };

    void hearByte(quint8 byte, qint64 nowMs);
    void hearBreak(qint64 nowMs);
    void write(const QByteArray& bytes, qint64 nowMs);
    void writeByte(quint8 byte, qint64 nowMs) { write(QByteArray(1, char(byte)), nowMs); }
    // The next byte is due from `user` (-1: an RID search, plain T).
    void expectWithin(qint64 nowMs, int user);
    // True (and counted) when the byte being heard came together with bytes
    // after it: the others did not wait for our answer, the line has gone
    // on, and an answer now would fall into somebody else's turn. A late
    // PC (a busy computer, a USB adapter's latency timer) then lets the turn
    // go instead of garbling the next one.
    bool lateToAnswer();
    // The byte awaited since expectWithin() came at nowMs (false: another
    // byte came instead).
    void answered(qint64 nowMs, bool theAnswer);
    void answerMissed();
    void tokenHeard(int user, qint64 nowMs);
    void blockHeard(qint64 nowMs);
    void endTurn(qint64 nowMs);
    void turnTimedOut(qint64 nowMs);
    void senderTurnFailed(const QString& problem);
    void finishHead(Delivery::Result result, const QString& problem);
    bool maySend() const;
    void ridHeard(int user, qint64 nowMs);
    void userFound(int user);
    void ridUnanswered();
    // Master
    void becomeMaster(qint64 nowMs);
    void masterNext(qint64 nowMs);
    qint64 wireMs(int bytes) const;

    CamBusStationConfig m_config;
    bool m_silent = false;
    QByteArray m_out;
    QByteArray m_pending;       // an undecoded FF at the end of the input
    bool m_lineWentOn = false;  // the byte being heard has others after it (feed)
    Phase m_phase = Phase::Idle;
    qint64 m_deadline = -1;       // a turn's answer or gap is due by then
    qint64 m_awaitedSince = -1;   // ... counted from then
    int m_awaitedUser = -1;       // ... from this user
    qint64 m_lastActivity = 0;    // own token, last break, last RID heard, start
    qint64 m_masterWaitEnd = -1;  // after breaks: master if no RID heard by then
    qint64 m_masterNextAt = -1;   // master: next token or RID then
    int m_tokenUser = -1;         // S of the turn in progress
    int m_destination = -1;       // D of the turn in progress
    int m_ridUser = -1;           // s searched last
    QByteArray m_block;           // block bytes collected
    bool m_init = false;          // in an initialisation phase (breaks heard, no token yet)
    bool m_master = false;
    bool m_joined = false;
    bool m_wantsBreakIn = false;
    int m_joinTries = 0;     // the PC's break-ins since it last had the token
    QList<int> m_table;      // master: the users found, ascending
    int m_nextIndex = 0;     // master: next user in m_table
    int m_ridRun = 0;        // master: RIDs in a row without a new user
    QSet<int> m_roundUsers;  // CB1: token users of the round going on
    bool m_roundWithoutUs = false;
    qint64 m_lineFreeAt = 0;  // our own bytes are on the wire until then
    qint64 m_deafUntil = 0;   // our breaks are on the wire until then
    std::deque<Outgoing> m_tx;
    quint64 m_nextId = 1;
    bool m_sendBit[64] = {};
    int m_acceptedBit[64];  // -1: either bit next (P8)
    QList<Delivery> m_deliveries;
    QList<Received> m_received;
    std::function<bool()> m_room;
    AnswerObserver m_answerObserver;
    CamBusView m_view;
};

}  // namespace cambench::comm
