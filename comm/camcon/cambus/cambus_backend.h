#pragma once

#include "cambus_station.h"
#include "cambus_view.h"

#include "comm/engine/framing_backend.h"

#include <memory>
#include <optional>

namespace cambench::comm {

// The CamCon ASCII protocol over the Cam-BUS as a FramingBackend: the PC is
// one user of the token bus (a CamBusStation with the PC's rules). A request
// becomes one block to the device, sent at the PC's next token; the request
// has left (`sent`) once the device acknowledged the block; the device's
// reply is a block to the PC at its own next token. Between requests the
// engine keeps feeding the line, so that the PC answers its DIDs and the
// bus keeps going (carriesOtherTraffic).
//
// No request numbers: a retry after a lost reply sends the request again as
// a new block, which the device executes again, so retries are as safe as
// in Standard framing (the command's RetryPolicy). A block that left but
// was not acknowledged is never resent under a new block bit; the attempt
// fails and says so.
class CamBusBackend : public FramingBackend {
public:
    CamBusBackend(int device, CamBusStationConfig config, CamBusMonitorPtr monitor = {});
    // The monitor goes back to "not on a bus": nothing stale stays shown as heard.
    ~CamBusBackend() override;

    int device() const { return m_device; }
    int pcNumber() const { return m_config.number; }
    void setDevice(int device) override;
    // Null until the first call with a time (the line is opened then).
    const CamBusStation* station() const { return m_station.get(); }
    // A probe: sends nothing at all, not even an answer to an RID (set
    // before the first call).
    void setListenOnly(bool listenOnly) { m_listenOnly = listenOnly; }
    // What the PC has seen of the bus so far.
    CamBusView view() const;
    // The bytes the PC's own exchanges put on the wire: its blocks and the
    // replies to it, each with the answers, TO and acknowledgement around
    // it (for the benchmark's wire limit).
    qint64 ownTrafficBytes() const { return m_ownBytes; }

    void setLineTiming(const LineTiming& line) override;
    QString describe() const override;
    QString checkHint() const override;
    void beginRequest(const Request& request) override;
    BackendStep startAttempt(const Request& request, int attempt, qint64 nowMs) override;
    BackendStep feed(QByteArrayView bytes, qint64 nowMs) override;
    BackendStep poll(qint64 nowMs) override;
    qint64 nextTimerMs() const override;
    QByteArray resetInput() override { return {}; }
    bool carriesOtherTraffic() const override { return true; }
    int replyLatencyMs() const override;
    qint64 requestWireBytes(const Request& request) const override;
    qint64 replyWireBytes(const Request& request) const override;
    QByteArray maskForLog(const QByteArray& wire, bool outgoing) const override;

private:
    CamBusStation& stationAt(qint64 nowMs);
    // The station's output, deliveries and received blocks as one step.
    BackendStep collect(qint64 nowMs);
    Incoming classify(const CamBusStation::Received& block) const;
    void noteRound();
    void publish(qint64 nowMs);
    // Why the request got no turn in time (the turn limit passed).
    QString noTurnMessage(int fullQueueAnswers, bool silentBus) const;
    // Said after a failure when the PC was too late to answer meanwhile
    // (empty when it kept the bus's timing).
    QString latenessNote() const;

    int m_device;
    CamBusStationConfig m_config;
    CamBusMonitorPtr m_monitor;
    std::unique_ptr<CamBusStation> m_station;
    std::optional<quint64> m_blockId;  // the request's block, until delivered or given up
    qint64 m_turnLimit = -1;           // no turn on the bus by then: the attempt fails
    qint64 m_lastOwnToken = -1;
    qint64 m_roundMs = 0;  // the longest recent time between two of our tokens
    qint64 m_published = -1;
    qint64 m_lastOwnBlocks = 0;
    qint64 m_ownBytes = 0;
    qint64 m_lateAtStart = 0;  // the station's late answers when the request started
    bool m_listenOnly = false;
    qint64 m_blockBytes = 0;  // wire bytes of the request's block in flight  // blocks the PC sent:
                              // a write with a new one is logged
};

}  // namespace cambench::comm
