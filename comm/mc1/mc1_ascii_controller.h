#pragma once

#include "mc1_ascii_backend.h"
#include "mc1_device.h"

#include "comm/engine/request_engine.h"

namespace cambench::comm {

// Mc1Device over the MC100's ASCII protocol ("mc1-ascii"): variables,
// flags, inputs and outputs one line each. It has no program, axis or
// memory requests; those are refused by name before anything is sent. The
// protocol cannot tell an MC100 V1 from a V2: the variant is MC100 V1.
// Reads and variable writes may be asked again after a lost answer; a
// flag or output write (`A9=1`) is sent once, and a lost answer is settled
// by reading the point back and saying what it holds.
class Mc1AsciiController : public Mc1Device {
public:
    Mc1AsciiController(Transport& transport, int timeoutMs, const LineTiming& line);

    QString protocolId() const override { return QStringLiteral("mc1-ascii"); }
    RequestEngine& engine() override { return m_engine; }
    Result<QString> identify() override;
    // "variant": "mc100": the protocol cannot tell V1 from V2.
    Result<DeviceIdentity> readIdentity() override;

    Mc1Variant variant() const override { return Mc1Variant::Mc100V1; }
    QString variantSource() const override;
    Result<Mc1Variant> ensureIdentified() override;
    bool has(Mc1Capability) const override { return false; }

    Result<qint64> readVariable(int number) override;
    Status writeVariable(int number, qint64 value) override;
    Result<QList<bool>> readPoints(const QList<Mc1Point>& points,
                                   const ProgressFn& progress) override;
    Result<bool> writePoint(const Mc1Point& point, bool on) override;
    Result<QByteArray> readExternalPage(quint8 page, const ProgressFn& progress) override;

    Result<Mc1ProgramStatus> programStatus() override;
    Result<Mc1Done<Mc1ProgramStatus>> programCommand(Mc1ProgramCommand command) override;
    Result<Mc1Axes> axes() override;
    Result<Mc1AxisState> axisState(int axis) override;
    Result<qint32> axisValue(int axis, Mc1AxisValue value) override;
    Result<Mc1AxisDone> axisCommand(int axis, Mc1AxisCommand command, qint32 value) override;
    Result<QByteArray> readMemory(int address, int length, const ProgressFn& progress) override;
    Status writeMemory(int address, const QByteArray& bytes, const ProgressFn& progress) override;

private:
    // One line out, the answer line back; `retry` Never sends it once.
    // `writes`: it changes the controller (Request::motion).
    Result<QByteArray> exchange(const QByteArray& line, RetryPolicy retry = RetryPolicy::Idempotent,
                                bool writes = false);
    Error notInAscii(const QString& what) const;

    Mc1AsciiBackend m_backend;
    RequestEngine m_engine;
    bool m_identified = false;
};

}  // namespace cambench::comm
