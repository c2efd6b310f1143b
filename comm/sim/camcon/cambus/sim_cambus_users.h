#pragma once

#include "comm/sim/camcon/sim_device.h"
#include "sim_cambus_medium.h"

#include <deque>
#include <memory>

namespace cambench::comm {

// A simulated CamCon on the Cam-BUS: its station takes blocks into a
// receive queue (4 waiting besides the one executing, P10); the oldest is
// executed once the one transmit buffer is free, and the reply goes to the
// requester at the next token. A frame with a bad ASCII checksum gets no
// reply (P7).
class SimCamBusCamCon : public SimCamBusUser {
public:
    SimCamBusCamCon(std::unique_ptr<SimDevice> device, const CamBusStationConfig& config,
                    qint64 nowMs);

    CamBusStation& station() override { return m_station; }
    SimDevice& device() { return *m_device; }
    // Executes what waits and queues replies.
    void service(qint64 nowMs) override;
    qint64 serviceTimerMs() const override { return m_readyAt; }
    int waiting() const { return int(m_waiting.size()); }
    int executed() const { return m_executed; }

private:
    std::unique_ptr<SimDevice> m_device;
    CamBusStation m_station;
    std::deque<CamBusStation::Received> m_waiting;
    bool m_executing = false;  // a reply is being worked on or waits in the transmit buffer
    qint64 m_readyAt = -1;     // the reply being worked on is ready then
    CamBusStation::Received m_current;
    QByteArray m_reply;
    int m_executed = 0;
};

// A display user (a CD10): asks one CamCon the same query again and again,
// one request at a time, and keeps what a technician would see: how many
// answers came and the longest pause between two.
class SimCamBusDisplay : public SimCamBusUser {
public:
    SimCamBusDisplay(int target, const CamBusStationConfig& config, qint64 nowMs);

    CamBusStation& station() override { return m_station; }
    void service(qint64 nowMs) override;
    int target() const { return m_target; }
    int answers() const { return m_answers; }
    qint64 longestPauseMs() const { return m_longestPauseMs; }
    // Starts the pause count afresh (after a join the test does not measure).
    void resetPauses(qint64 nowMs);

private:
    CamBusStation m_station;
    int m_target;
    bool m_asking = false;
    qint64 m_askedAt = -1;
    qint64 m_lastAnswerMs = -1;
    qint64 m_longestPauseMs = 0;
    int m_answers = 0;
};

}  // namespace cambench::comm
