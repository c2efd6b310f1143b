#pragma once

#include "sim_endpoint.h"
#include "sim_pacer.h"
#include "sim_reply_scheduler.h"

#include "model/result.h"

#include <QObject>
#include <QSocketNotifier>

#include <memory>

namespace cambench::comm {

// Serves a SimEndpoint on a pseudo-terminal: a program opens slavePath() as if
// it were a serial port. Both sides are raw: a cooked tty would eat 0x03,
// 0x15 and XON/XOFF and rewrite CR/LF.
class SimPtyServer : public QObject {
    Q_OBJECT

public:
    SimPtyServer(SimEndpoint& line, const SimPacer& pacer, QObject* parent = nullptr);
    ~SimPtyServer() override;

    Status open();
    QString slavePath() const { return m_slavePath; }

private:
    void onReadable();
    void write(const QByteArray& bytes);

    int m_master = -1;
    // Kept open so that the master does not see a hang-up (EIO) while no
    // client has the slave open.
    int m_slave = -1;
    QString m_slavePath;
    std::unique_ptr<QSocketNotifier> m_notifier;
    SimReplyScheduler m_scheduler;
};

}  // namespace cambench::comm
