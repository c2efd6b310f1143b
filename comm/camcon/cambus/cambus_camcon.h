#pragma once

#include "cambus_backend.h"

#include "comm/camcon/ascii/ascii_camcon.h"

namespace cambench::comm {

// A CamCon reached over the Cam-BUS: every ASCII operation of AsciiCamCon,
// each request a block on the token bus (CamBusBackend), and a scan that
// lists the users the bus knows with what they are.
class CamBusCamCon : public AsciiCamCon {
public:
    CamBusCamCon(Transport& transport, const AsciiSettings& settings, const LineTiming& line,
                 const CamBusStationConfig& station, CamBusMonitorPtr monitor);

    QString protocolId() const override;
    // Detect: only listens (no byte that would disturb the bus, no breaks)
    // and names the users that pass the token.
    Result<QString> probe() override;
    bool has(CamConCapability capability) const override;

    // The users the bus passes the token to (and the ones an RID search
    // found): each other user is asked ?UNIT once; a CamCon answers, a
    // display or another PC does not.
    Result<BusUsers> scanUsers(const ProgressFn& progress = {}) override;
    // The CamCons among them, in [first, last].
    using AsciiCamCon::scanBus;
    Result<QList<int>> scanBus(int first, int last, const ProgressFn& progress = {}) override;

    CamBusBackend& bus() { return m_bus; }

private:
    // Listens until a whole round of the token went by (or the time is up).
    Status learnRound();

    CamBusBackend& m_bus;
};

}  // namespace cambench::comm
