#pragma once

#include "mc1_axis_motion.h"
#include "mc1_backend.h"
#include "mc1_device.h"
#include "mc1_link.h"

#include "comm/engine/request_engine.h"

#include <optional>

namespace cambench::comm {

// How CamBench talks to an MC100/MC200: the variant (none: probe it), the
// user's fixed timeout and the retries of the telegrams that may repeat.
struct Mc1Settings {
    std::optional<Mc1Variant> variant;
    int timeoutMs = 0;
    int retries = 2;
    // The axes to use instead of finding them with RDTABLE (none: find them).
    std::optional<QList<int>> axes;
};

// Whether the telegram of `command` may be sent again after a lost answer
// (mc1AxisRetry of its opcode and command byte).
Mc1Retry mc1AxisCommandRetry(Mc1AxisCommand command);

// Mc1Device over the binary MC-1 protocol (RS232, any variant).
class Mc1Controller : public Mc1Device {
public:
    Mc1Controller(Transport& transport, const Mc1Settings& settings, const LineTiming& line);

    QString protocolId() const override { return QStringLiteral("mc1"); }
    RequestEngine& engine() override { return m_engine; }
    Result<QString> identify() override;
    // The variant, RDTABLE's axis table (MC200) and the UDB address
    // (MC200 V2): mc1_controller_identity.cpp.
    Result<DeviceIdentity> readIdentity() override;
    // identify() without retries, but for one: an MC100MA single-FIFO card
    // loses the first telegram, sent before the line was heard; when its
    // 0xFF was heard meanwhile, the identification is asked again, in step
    // with the 0xFF and with the usual retries (reads only).
    Result<QString> probe() override;

    Mc1Variant variant() const override { return m_link.variant(); }
    QString variantSource() const override { return m_source; }
    Result<Mc1Variant> ensureIdentified() override;
    bool has(Mc1Capability capability) const override;

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
    // The axis command's telegram alone, no read-back: `maxAttempts` > 0
    // caps its attempts below what its repeat rule allows. A stop goes out
    // to a controller not identified yet, unprobed: a STOP never waits.
    Status sendAxisCommand(int axis, Mc1AxisCommand command, qint32 value, int maxAttempts = 0);
    // The axes of an MC200 V2 can be stopped from anywhere; nullptr for a
    // variant without axis telegrams. Sends nothing: a controller not
    // identified yet gets a STOP (that may be refused) unless the settings
    // name a variant without axes.
    MotionControl* motionControl() override;
    // The axes given, or those RDTABLE found; none before the search.
    std::optional<Mc1Axes> knownAxes() const;

    Result<QByteArray> readMemory(int address, int length, const ProgressFn& progress) override;
    Status writeMemory(int address, const QByteArray& bytes, const ProgressFn& progress) override;

private:
    // Link and backend speak `variant` from now on.
    void use(Mc1Variant variant);
    // The variant's width (MC100 or MC200) and whether SYSDATA or RDBLOCK
    // answer: what a probe can tell.
    Result<Mc1Variant> probeVariant();
    // The identified variant, once `variable` is a number RDVAR/WRVAR carry.
    Result<Mc1Variant> identifiedFor(int variable);
    // An Unsupported error unless the identified variant has `capability`.
    Status require(Mc1Capability capability, const QString& what);
    // `bytes` bytes of internal RAM (`external` false) or of an external
    // page from `address` on.
    Result<QByteArray> readRam(bool external, quint8 page, int address, int count,
                               const ProgressFn& progress);
    // Usage error unless the variant has axes and `axis` is one of 1..8.
    Status canReadAxis(int axis);
    // Usage error unless `axis` is one of the logical axes 1..8.
    Status checkAxisNumber(int axis) const;
    // Usage error naming the axes there are unless `present` holds `axis`.
    Status checkAxisExists(int axis, const Mc1Axes& present) const;
    // One axis value through the parameter table; a refusal names the
    // parameter and, for the built-in guess, what to load.
    Result<qint32> readAxisValue(int axis, Mc1AxisValue value);
    // RDTABLE for every logical axis: those the controller has.
    Result<QList<int>> findAxes();

    Mc1Backend m_backend;
    RequestEngine m_engine;
    Mc1Link m_link;
    std::optional<Mc1Variant> m_given;
    bool m_identified = false;
    QString m_source;
    std::optional<Mc1Axes> m_found;  // what RDTABLE answered, once
    Mc1AxisMotion m_motion{*this};
};

}  // namespace cambench::comm
