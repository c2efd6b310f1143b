#pragma once

#include "sim_cambus_medium.h"
#include "sim_cambus_users.h"

#include "comm/sim/camcon/sim_camcon_endpoint.h"

#include <QMap>
#include <QSet>

#include <memory>
#include <vector>

namespace cambench::comm {

// How the PC answered the simulated users, as they judge it against T:
// each answer's time after the byte it answers (to the ms the simulated bus
// counts in) and the answers that did not come in time (the turn ended;
// counted once the PC answered again, so that a PC that has gone is not
// counted as one that misses).
struct SimPcAnswers {
    QMap<qint64, qint64> countByMs;
    qint64 missed = 0;

    qint64 count() const;
    qint64 medianMs() const;  // -1: none yet
    qint64 worstMs() const;   // -1: none yet
};

// A simulated Cam-BUS behind one of the simulator's ports: CamCons,
// display users polling them, the wire between them, and the PC on
// the far side of the port. The bus runs by itself on the host's clock
// (poll()), whether the PC says anything or not.
class SimCamBusLine : public SimCamConEndpoint {
public:
    struct Setup {
        int baud = 38400;
        // Display users: the i-th polls the i-th CamCon (round and round).
        QList<int> displays;
        QList<int> silent;        // users that never answer (a dead device)
        qint64 silentFromMs = 0;  // ... from then on (0: from the start; a user that falls silent)
        qint64 reinitAtMs = -1;   // >= 0: the first CamCon breaks in then (a second initialisation)
        // How long the simulated users wait for the PC (a user not simulated
        // here) to answer: T (P11) unless a loaded test machine needs more.
        int pcAnswerMs = 10;
        CamBusStationConfig station;  // timing for every simulated user
        SimCamBusFaults faults;
    };

    SimCamBusLine(std::vector<std::unique_ptr<SimDevice>> devices, const Setup& setup,
                  qint64 nowMs);
    // Logs how the PC answered (information: cambench-sim --verbose).
    ~SimCamBusLine() override;

    SimDevice* device(int number) const override;
    SimCamBusCamCon* camCon(int number) const;
    // The display users, in the order of Setup::displays.
    SimCamBusDisplay* display(int index = 0) const;
    int displayCount() const { return int(m_displays.size()); }
    SimCamBusMedium& medium() { return m_medium; }

    QList<SimOutput> receive(QByteArrayView bytes, qint64 nowMs) override;
    QList<SimOutput> poll(qint64 nowMs) override;
    qint64 nextTimerMs() const override;
    QString protocolName() const override { return QStringLiteral("Cam-BUS"); }

private:
    static QList<SimOutput> outputs(const QByteArray& bytes);
    // The faults that come at a time: a user falling silent, a second
    // initialisation phase.
    void applyScheduledFaults(qint64 nowMs);
    // An answer the simulated users awaited from the PC (-1: missed).
    void notePcAnswer(int user, qint64 ms);

    std::vector<std::unique_ptr<SimCamBusCamCon>> m_camCons;
    std::vector<std::unique_ptr<SimCamBusDisplay>> m_displays;
    SimCamBusMedium m_medium;
    QList<int> m_fallSilent;
    qint64 m_silentFromMs = -1;  // -1: done
    qint64 m_reinitAtMs = -1;    // -1: done
    // Numbers the PC answered for: they get Setup::pcAnswerMs.
    std::shared_ptr<QSet<int>> m_external = std::make_shared<QSet<int>>();
    int m_pcAnswerMs = 10;
    SimPcAnswers m_pcAnswers;
    qint64 m_pcMissesPending = 0;  // since the PC's last answer
    int m_initPhasesSeen = 0;
};

}  // namespace cambench::comm
