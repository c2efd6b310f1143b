#pragma once

#include "comm/camcon/ascii/frame.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <atomic>
#include <functional>
#include <mutex>
#include <thread>

namespace cambench::comm::test {

// What the scripted device does with one request.
struct DeviceAction {
    QList<QByteArray> chunks;  // written one after another
    int chunkDelayMs = 0;      // pause before each chunk
    bool hangUp = false;       // close the master afterwards: the port vanishes
};

// A device on the master side of a real pseudo-terminal pair. The code
// under test opens slavePath() with QSerialPort; a thread of this class
// decodes what arrives on the master and answers as the script says.
class PtyDevice {
public:
    // `index` counts the requests received so far, from 0.
    using Script = std::function<DeviceAction(const Frame& request, int index)>;

    explicit PtyDevice(Framing framing, Script script);
    ~PtyDevice();

    bool isValid() const { return !m_slavePath.isEmpty(); }
    QString slavePath() const { return m_slavePath; }
    // The slave's terminal settings as the code under test left them.
    int slaveFd() const { return m_slave; }

    QList<Frame> requests() const;
    int requestCount() const;
    bool hungUp() const { return m_hungUp.load(); }

private:
    void run();
    void writeAll(const QByteArray& bytes);

    Framing m_framing;
    Script m_script;
    int m_master = -1;
    int m_slave = -1;
    QString m_slavePath;
    mutable std::mutex m_mutex;
    QList<Frame> m_requests;
    std::atomic_bool m_stop{false};
    std::atomic_bool m_hungUp{false};
    std::thread m_thread;
};

// The reply frame to `request` with `body`: in Multiuser with the header a
// device sends back (its number, the PC's number, the same block).
QByteArray replyTo(const Frame& request, const QByteArray& body);
QByteArray replyFrom(const Frame& request, const QByteArray& body, int device, int block);
// The same reply with its checksum made wrong.
QByteArray withBadChecksum(QByteArray wire);

}  // namespace cambench::comm::test
