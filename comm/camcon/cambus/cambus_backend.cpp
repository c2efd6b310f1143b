#include "cambus_backend.h"

#include "cambus_payload.h"

#include "comm/camcon/ascii/traffic_mask.h"

#include <QCoreApplication>

#include <algorithm>

namespace cambench::comm {

namespace {

// The longest a request waits for its turn: joining a bus takes 1250 ms of
// listening and an initialisation phase (~2 s with 64 numbers to search).
constexpr qint64 kTurnLimitMs = 10000;
// A round of the token before one was measured.
constexpr qint64 kUnmeasuredRoundMs = 250;
// How often the bus view is handed to the GUI.
constexpr qint64 kPublishMs = 100;

// The bytes around a request's data on the wire: LEN, the two checksum
// characters of the frame and the two of the block, our DID answer and TO,
// the device's room answer and acknowledgement.
constexpr int kBlockOverhead = 1 + 2 + 2 + 2 + 2;

}  // namespace

CamBusBackend::CamBusBackend(int device, CamBusStationConfig config, CamBusMonitorPtr monitor)
    : m_device(std::clamp(device, 0, kCamBusLastUser)),
      m_config(config),
      m_monitor(std::move(monitor)) {
    m_config.joinBeforeFirstBlock = true;
    if (m_monitor) m_monitor->clear();
}

CamBusBackend::~CamBusBackend() {
    if (m_monitor) m_monitor->clear();
}

void CamBusBackend::setDevice(int device) {
    m_device = std::clamp(device, 0, kCamBusLastUser);
}

void CamBusBackend::setLineTiming(const LineTiming& line) {
    if (line.baud > 0) m_config.baud = line.baud;
}

CamBusView CamBusBackend::view() const {
    return m_station ? m_station->view() : CamBusView{};
}

QString CamBusBackend::describe() const {
    return QCoreApplication::translate("cambench::comm", "Cam-BUS device %1 (PC %2)")
        .arg(m_device)
        .arg(m_config.number);
}

QString CamBusBackend::checkHint() const {
    return QCoreApplication::translate(
               "cambench::comm",
               "check that device %1 is on the Cam-BUS (scan lists its users), the RS485 "
               "wiring and 38400 baud, and that no other user has the PC's number %2")
        .arg(m_device)
        .arg(m_config.number);
}

CamBusStation& CamBusBackend::stationAt(qint64 nowMs) {
    if (!m_station) {
        m_station = std::make_unique<CamBusStation>(m_config, nowMs);
        m_station->setSilent(m_listenOnly);
    }
    return *m_station;
}

void CamBusBackend::beginRequest(const Request& request) {
    Q_UNUSED(request);
}

BackendStep CamBusBackend::startAttempt(const Request& request, int attempt, qint64 nowMs) {
    Q_UNUSED(attempt);
    CamBusStation& station = stationAt(nowMs);
    // One request per device (docs/protocols/cambus.md): an earlier attempt's block that has not
    // left yet goes.
    station.cancelUnsent(m_device);
    BackendStep step;
    const QByteArray data = request.message.isEmpty()
                                ? QByteArray()
                                : camBusPayload(request.message.at(0), request.message.mid(1));
    if (data.isEmpty() || data.size() > kCamBusMaxData) {
        step.linkFailure =
            QCoreApplication::translate("cambench::comm",
                                        "%1 needs %2 bytes, more than a Cam-BUS block "
                                        "holds (255)")
                .arg(request.label)
                .arg(data.size());
        return step;
    }
    station.resetJoinTries();
    m_lateAtStart = station.view().lateAnswers;
    m_blockId = station.send(m_device, data);
    m_blockBytes = data.size() + kBlockOverhead - 2;
    m_turnLimit = nowMs + kTurnLimitMs;
    station.poll(nowMs);
    step.append(collect(nowMs));
    return step;
}

BackendStep CamBusBackend::feed(QByteArrayView bytes, qint64 nowMs) {
    stationAt(nowMs).feed(bytes, nowMs);
    return collect(nowMs);
}

BackendStep CamBusBackend::poll(qint64 nowMs) {
    CamBusStation& station = stationAt(nowMs);
    station.poll(nowMs);
    BackendStep step = collect(nowMs);
    if (m_blockId && station.gaveUpJoining() && station.cancel(*m_blockId)) {
        m_blockId.reset();
        m_turnLimit = -1;
        step.linkFailure =
            QCoreApplication::translate(
                "cambench::comm",
                "the PC could not join the Cam-BUS: after %1 initialisation phases the master "
                "still passes user %2 no token (its answers may come too late for the bus: a USB "
                "adapter's latency timer should be 1 ms; or another user has number %2); the "
                "request was not sent")
                .arg(CamBusStation::kMaxJoinTries)
                .arg(m_config.number) +
            latenessNote();
        return step;
    }
    if (m_blockId && m_turnLimit >= 0 && nowMs >= m_turnLimit) {
        const int full = station.fullQueueAnswers(*m_blockId);
        // It is leaving: its outcome comes. The limit stays armed, since a
        // device whose queue is still full sends it back to the queue, and
        // then the next poll takes it off.
        if (!station.cancel(*m_blockId)) return step;
        m_turnLimit = -1;
        m_blockId.reset();
        step.linkFailure = noTurnMessage(full, station.view().users.isEmpty()) + latenessNote();
    }
    return step;
}

QString CamBusBackend::noTurnMessage(int fullQueueAnswers, bool silentBus) const {
    const int seconds = int(kTurnLimitMs / 1000);
    if (fullQueueAnswers > 0)
        return QCoreApplication::translate("cambench::comm",
                                           "device %1's receive queue stayed full for %2 s (it "
                                           "refused the request %3 times); the request was not "
                                           "sent")
            .arg(m_device)
            .arg(seconds)
            .arg(fullQueueAnswers);
    if (silentBus)
        return QCoreApplication::translate("cambench::comm",
                                           "no Cam-BUS traffic: no user passed the token in %1 s")
            .arg(seconds);
    return QCoreApplication::translate("cambench::comm",
                                       "the PC (user %1) got no turn on the Cam-BUS in %2 s")
        .arg(m_config.number)
        .arg(seconds);
}

QString CamBusBackend::latenessNote() const {
    const qint64 late = m_station ? m_station->view().lateAnswers - m_lateAtStart : 0;
    if (late <= 0) return {};
    // Counted before the call: lupdate (Qt 6.4) hangs on a template call
    // among translate()'s arguments.
    const int times = int(std::min<qint64>(late, 1000000));
    return QCoreApplication::translate(
               "cambench::comm",
               "; the PC was too late to answer on the bus %n time(s) during this request (the "
               "bus waits %1 ms for an answer: a USB adapter's latency timer should be 1 ms, "
               "and a computer this busy is too slow for the bus)",
               nullptr, times)
        .arg(m_config.answerMs);
}

qint64 CamBusBackend::nextTimerMs() const {
    if (!m_station) return -1;
    qint64 next = m_station->nextTimerMs();
    if (m_blockId && m_turnLimit >= 0 && (next < 0 || m_turnLimit < next)) next = m_turnLimit;
    return next;
}

BackendStep CamBusBackend::collect(qint64 nowMs) {
    CamBusStation& station = *m_station;
    BackendStep step;
    step.write = station.takeOutput();
    const qint64 ownBlocks = station.view().users.value(m_config.number).blocks;
    step.quiet = ownBlocks == m_lastOwnBlocks;
    m_lastOwnBlocks = ownBlocks;
    for (const CamBusStation::Delivery& delivery : station.takeDeliveries()) {
        if (!m_blockId || delivery.id != *m_blockId) continue;
        m_blockId.reset();
        m_turnLimit = -1;
        switch (delivery.result) {
            case CamBusStation::Delivery::Delivered:
                step.sent = true;
                m_ownBytes += m_blockBytes;
                break;
            case CamBusStation::Delivery::NotTaken:
                step.linkFailure = QCoreApplication::translate(
                                       "cambench::comm",
                                       "device %1 did not take the request in %2 turns (%3); "
                                       "it was not executed")
                                       .arg(delivery.destination)
                                       .arg(m_config.maxSilentTurns)
                                       .arg(delivery.problem) +
                                   latenessNote();
                break;
            case CamBusStation::Delivery::Uncertain:
                step.linkFailure = QCoreApplication::translate(
                                       "cambench::comm",
                                       "the request went to device %1 but was not acknowledged "
                                       "(%2); it may have been executed")
                                       .arg(delivery.destination)
                                       .arg(delivery.problem) +
                                   latenessNote();
                break;
        }
    }
    for (const CamBusStation::Received& block : station.takeReceived()) {
        m_ownBytes += block.data.size() + kBlockOverhead - 2;
        step.incoming << classify(block);
    }
    noteRound();
    publish(nowMs);
    return step;
}

Incoming CamBusBackend::classify(const CamBusStation::Received& block) const {
    Incoming in;
    in.wire = block.data;
    in.source = block.source;
    if (block.source != m_device) {
        in.kind = Incoming::Foreign;
        return in;
    }
    const Result<Frame> frame = parseCamBusPayload(block.data);
    if (!frame) {
        in.kind = Incoming::Damaged;
        in.detail = frame.error().message;
        return in;
    }
    in.kind = Incoming::Message;
    in.message = frame->lead + frame->body;
    return in;
}

void CamBusBackend::noteRound() {
    const qint64 token = m_station->view().users.value(m_config.number).lastTokenMs;
    if (token < 0 || token == m_lastOwnToken) return;
    if (m_lastOwnToken >= 0) {
        const qint64 round = token - m_lastOwnToken;
        // The longest recent round counts; an old long one fades.
        m_roundMs = std::max(round, m_roundMs * 7 / 8);
    }
    m_lastOwnToken = token;
}

int CamBusBackend::replyLatencyMs() const {
    // The device answers at its next turn: up to two rounds of the token.
    const qint64 round = m_roundMs > 0 ? m_roundMs : kUnmeasuredRoundMs;
    return int(2 * round + m_config.answerMs);
}

void CamBusBackend::publish(qint64 nowMs) {
    if (!m_monitor || (m_published >= 0 && nowMs - m_published < kPublishMs)) return;
    m_published = nowMs;
    CamBusView view = m_station->view();
    view.nowMs = nowMs;
    m_monitor->publish(view);
}

qint64 CamBusBackend::requestWireBytes(const Request& request) const {
    return request.message.size() + kBlockOverhead;
}

qint64 CamBusBackend::replyWireBytes(const Request& request) const {
    // The device's token comes before its reply.
    return request.longestReplyBytes + kBlockOverhead + 4;
}

QByteArray CamBusBackend::maskForLog(const QByteArray& wire, bool outgoing) const {
    // A block (LEN, frame, CHK1, CHK2) or a received block's frame.
    const bool block = wire.size() > 3 && quint8(wire.at(0)) + 3 == wire.size();
    if (!block) return maskSecrets(wire, outgoing);
    return wire.left(1) + maskSecrets(wire.mid(1, wire.size() - 3), outgoing) + wire.right(2);
}

}  // namespace cambench::comm
