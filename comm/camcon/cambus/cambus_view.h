#pragma once

#include <QMap>
#include <QtGlobal>

#include <memory>
#include <mutex>

namespace cambench::comm {

// What one user has seen of the bus: the users that got the token (or
// answered an RID) since the last initialisation phase, who holds the
// token, who is master. For the bus view and `scan`.
struct CamBusUserState {
    qint64 lastTokenMs = -1;  // -1: found by its RID answer, no token yet
    bool answers = true;      // answered its last DID (a silent user stays in the table, P4)
    qint64 blocks = 0;        // blocks it sent
};

struct CamBusView {
    QMap<int, CamBusUserState> users;
    int tokenHolder = -1;
    // The winner of the last initialisation phase: the lowest number that
    // answered an RID (the master cannot be told from the bytes otherwise).
    int master = -1;
    int initPhases = 0;  // heard since the start
    qint64 tokens = 0;   // tokens heard since the start
    // Turns this user was too late for: it heard what it was to answer
    // only with bytes after it (and let the turn go), or another user's
    // byte came instead of the answer to its TO. Its answers do not keep T.
    qint64 lateAnswers = 0;
    bool inInitPhase = false;
    qint64 nowMs = 0;  // when this was taken
};

// The view handed from the worker thread to the GUI: the backend publishes,
// the bus view reads; a mutex, nothing else shared.
class CamBusMonitor {
public:
    // The one the GUI's bus view reads: CamBench holds one connection at a time.
    static const std::shared_ptr<CamBusMonitor>& shared() {
        static const std::shared_ptr<CamBusMonitor> monitor = std::make_shared<CamBusMonitor>();
        return monitor;
    }

    void publish(const CamBusView& view) {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_view = view;
        m_published = true;
    }
    // False until the first publish (not connected over Cam-BUS yet).
    bool read(CamBusView& view) const {
        std::lock_guard<std::mutex> lock(m_mutex);
        view = m_view;
        return m_published;
    }
    void clear() {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_view = {};
        m_published = false;
    }

private:
    mutable std::mutex m_mutex;
    CamBusView m_view;
    bool m_published = false;
};

using CamBusMonitorPtr = std::shared_ptr<CamBusMonitor>;

}  // namespace cambench::comm
