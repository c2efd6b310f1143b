#include "sim_cambus_users.h"

#include "comm/camcon/cambus/cambus_payload.h"

#include <algorithm>

namespace cambench::comm {

namespace {
constexpr int kQueueDepth = 4;  // P10: waiting blocks, besides the one executing
// A display gives up on an unanswered query after this and asks again.
constexpr qint64 kDisplayPatienceMs = 2000;
}  // namespace

SimCamBusCamCon::SimCamBusCamCon(std::unique_ptr<SimDevice> device,
                                 const CamBusStationConfig& config, qint64 nowMs)
    : m_device(std::move(device)), m_station(config, nowMs) {
    m_station.setRoomCheck([this] { return int(m_waiting.size()) < kQueueDepth; });
}

void SimCamBusCamCon::service(qint64 nowMs) {
    for (CamBusStation::Received& block : m_station.takeReceived())
        m_waiting.push_back(std::move(block));
    for (const CamBusStation::Delivery& delivery : m_station.takeDeliveries()) {
        Q_UNUSED(delivery);
        m_executing = false;  // the transmit buffer is free again
    }
    if (m_executing && m_readyAt >= 0 && nowMs >= m_readyAt) {
        m_readyAt = -1;
        m_station.send(m_current.source, m_reply);
    }
    while (!m_executing && !m_waiting.empty()) {
        m_current = m_waiting.front();
        m_waiting.pop_front();
        const Result<Frame> request = parseCamBusPayload(m_current.data);
        if (!request) continue;  // a bad ASCII checksum: no reply
        ++m_executed;
        const std::optional<SimDevice::Reply> reply = m_device->execute(*request);
        if (!reply) continue;
        m_reply = camBusPayload(reply->frame.lead, reply->frame.body);
        m_executing = true;
        m_readyAt = nowMs + std::max(0, reply->delayMs);
    }
}

SimCamBusDisplay::SimCamBusDisplay(int target, const CamBusStationConfig& config, qint64 nowMs)
    : m_station(config, nowMs), m_target(target) {}

void SimCamBusDisplay::resetPauses(qint64 nowMs) {
    m_longestPauseMs = 0;
    m_lastAnswerMs = nowMs;
}

void SimCamBusDisplay::service(qint64 nowMs) {
    for (const CamBusStation::Received& block : m_station.takeReceived()) {
        if (block.source != m_target || !parseCamBusPayload(block.data)) continue;
        ++m_answers;
        if (m_lastAnswerMs >= 0)
            m_longestPauseMs = std::max(m_longestPauseMs, nowMs - m_lastAnswerMs);
        m_lastAnswerMs = nowMs;
        m_asking = false;
    }
    for (const CamBusStation::Delivery& delivery : m_station.takeDeliveries())
        if (delivery.result != CamBusStation::Delivery::Delivered) m_asking = false;
    if (m_asking && nowMs - m_askedAt > kDisplayPatienceMs) m_asking = false;
    if (!m_asking && !m_station.hasQueued()) {
        // A query every CamCon answers (its device number).
        m_station.send(m_target, camBusPayload(kQuery, "GNR"));
        m_asking = true;
        m_askedAt = nowMs;
    }
}

}  // namespace cambench::comm
