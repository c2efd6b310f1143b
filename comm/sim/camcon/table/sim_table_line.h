#pragma once

#include "sim_table_device.h"

#include "comm/camcon/table/link_3964r.h"
#include "comm/sim/camcon/sim_camcon_endpoint.h"
#include "comm/sim/sim_faults.h"

#include <QRandomGenerator>

#include <memory>

namespace cambench::comm {

class SimDevice;

// A point-to-point 3964R line to one simulated CamCon speaking its table
// interface: the device's Link3964R (low priority) answers the PC's
// handshakes, SimTableDevice executes each telegram, and the reply goes
// back as the device's own 3964R transfer.
//
// Faults, each per chance from one seeded generator (SimFaultSettings):
// NAK instead of the DLE after a good block (not executed); a lost DLE of
// the device (after the PC's STX, or after its block: executed, the PC
// does not know); a corrupted BCC in the device's reply block (the PC
// answers NAK, the device repeats); an STX of the device crossing the PC's
// (it yields, low priority); a reply never sent (drop).
//
// A telegram the PC sends while the device still tries to deliver the
// reply to the one before supersedes that reply (the PC gave up on it): the
// device drops it and answers the new one. Provisional: the manuals do not
// say what a CamCon does then.
class SimTableLine : public SimCamConEndpoint {
public:
    struct Counters {
        int telegrams = 0;  // executed
        int naks = 0;
        int lostDles = 0;
        int corruptBccs = 0;
        int collisions = 0;
        int droppedReplies = 0;
        int supersededReplies = 0;
    };

    SimTableLine(table::Rk512Variant variant, std::unique_ptr<SimDevice> device);
    ~SimTableLine() override;

    void setFaults(const SimFaultSettings& faults);
    const Counters& counters() const { return m_counters; }
    table::Rk512Variant variant() const { return m_table.variant(); }

    QList<SimOutput> receive(QByteArrayView bytes, qint64 nowMs) override;
    QList<SimOutput> poll(qint64 nowMs) override;
    qint64 nextTimerMs() const override { return m_link.nextDeadlineMs(); }
    SimDevice* device(int number) const override;
    QString protocolName() const override;

private:
    // Applies faults to what the link wants written and executes what it
    // received; `fromPoll`: a timer, not bytes, caused it.
    QList<SimOutput> handle(table::Actions&& actions, qint64 nowMs);
    bool chance(double probability);

    std::unique_ptr<SimDevice> m_device;
    SimTableDevice m_table;
    table::Link3964R m_link;
    SimFaultSettings m_faults;
    QRandomGenerator m_random;
    Counters m_counters;
};

}  // namespace cambench::comm
