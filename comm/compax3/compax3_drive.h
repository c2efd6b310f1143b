#pragma once

#include "compax3_backend.h"
#include "compax3_device.h"
#include "compax3_syntax.h"

#include "comm/engine/request_engine.h"

namespace cambench::comm {

// Compax3Device over the ASCII protocol: one request line, one answer line.
// Also the shell's MotionControl of the drive's axis.
class Compax3Drive : public Compax3Device, public MotionControl {
public:
    // `address` 0..99 on RS485, -1 on RS232; `protocolId` "compax3" or
    // "compax3-rs485".
    Compax3Drive(Transport& transport, QString protocolId, int address, int timeoutMs,
                 const LineTiming& line);

    QString protocolId() const override { return m_protocolId; }
    RequestEngine& engine() override { return m_engine; }
    Result<QString> identify() override;
    // On RS485 the drive may have any address: the probe looks at each
    // (a short wait each) and identifies the first that answers.
    Result<QString> probe() override;
    Result<QList<int>> scanBus(int first, int last, const ProgressFn& progress) override;
    void setDevice(int device) override;

    Result<Compax3Identity> identity() override;
    Result<QString> readObject(const Compax3ObjectId& id, bool hex) override;
    Status writeObject(const Compax3ObjectId& id, const QString& wireValue) override;
    Result<Compax3DriveStatus> status() override;
    Result<Compax3CommandResult> motion(Compax3Motion motion) override;
    Result<Compax3SetValues> readSet(int set) override;
    Result<Compax3CommandResult> moveSet(const Compax3SetMove& move) override;

    MotionControl* motionControl() override { return this; }
    MotionStopReport stopAllMotion() override;
    Result<QStringList> activeMotion() override;

private:
    // One command out, its answer back; a '!xxxx' answer becomes the
    // refusal error.
    // `maxAttempts` > 0: at most that many (RequestEngine's default otherwise).
    Result<Compax3Reply> exchange(const QByteArray& command, RetryPolicy retry,
                                  int longestReply = 24, int maxAttempts = 0);
    // A write or function: '>' expected.
    Status writeCommand(const QByteArray& command, RetryPolicy retry);
    Result<QString> readValue(const Compax3ObjectId& id, bool hex, int maxAttempts);
    Result<double> readNumber(const Compax3ObjectId& id, int maxAttempts = 0);
    // The control word, sent once when it moves the axis. A lost answer:
    // the state read back, in the error.
    Result<Compax3CommandResult> sendControl(quint16 word, const QString& what, RetryPolicy retry);
    Result<Compax3CommandResult> enable(const QString& what);
    // STOP that changes nothing but motion (compax3_drive_stop.cpp).
    Result<Compax3CommandResult> stop(const QString& what);
    // "Compax3 drive at address 3", for STOP's report.
    QString driveName() const;

    QString m_protocolId;
    Compax3Backend m_backend;
    RequestEngine m_engine;
    bool m_stopping = false;  // the stop's writes are going out: no Request::motion
};

}  // namespace cambench::comm
