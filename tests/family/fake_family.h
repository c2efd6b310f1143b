#pragma once

// A minimal device family that exists only in the tests (issue 13, point 6):
// one protocol ("fake-line": a text line per request and reply), its
// device interface, a simulator, one GUI page and one CLI command group.
// It is registered into the same registries the built-in families use,
// from the test alone: the shell must host it without an edit outside.

#include "app/registry/family_parts.h"
#include "comm/device/device_connection.h"
#include "comm/device/family_registry.h"
#include "comm/device/motion_control.h"
#include "comm/device/protocol_registry.h"
#include "comm/engine/framing_backend.h"
#include "model/device_identity.h"

#include <QAtomicInt>
#include <QStringList>

namespace cambench::fake {

// The device interface of the family: what its page and command use. Its
// axes (how many, and one that never acknowledges a STOP, come from the
// simulator's port: "sim:throttle=0,axes=2,deaf=2") move on "MOVE n" until
// "STOP n": the MotionControl the shell's STOP is tested with. Its
// registers ("regs=4", each n starting at serial × 100 + n) and serial
// number ("serial=1") are what its backup holds (fake_backup.h).
class FakeDevice : public comm::DeviceConnection, public comm::MotionControl {
public:
    FakeDevice(comm::Transport& transport, const comm::LineTiming& line);
    ~FakeDevice() override;

    QString familyId() const override { return QStringLiteral("fake"); }
    QString protocolId() const override { return QStringLiteral("fake-line"); }
    comm::RequestEngine& engine() override;
    Result<QString> identify() override;
    // "PING n" -> "PONG n".
    Result<QString> ping(int n);
    // Starts axis `axis` (1-based) moving.
    Result<QString> move(int axis);

    // What identify() found: the serial number ("serial=3" on the port)
    // tells two fake devices apart; how many registers the device has.
    DeviceIdentity identity() const;
    int registers() const;
    // identify(), then identity(): what a machine and a restore compare.
    Result<DeviceIdentity> readIdentity() override;
    // Register n (1-based): "GET n" -> "VAL n v"; "SET n v" -> "VAL n v".
    // Setting a register to a value twice leaves it as once: a retry is safe.
    Result<qint32> readRegister(int n);
    Result<qint32> writeRegister(int n, qint32 value);

    MotionControl* motionControl() override { return this; }
    comm::MotionStopReport stopAllMotion() override;
    Result<QStringList> activeMotion() override;

private:
    struct Impl;
    std::unique_ptr<Impl> d;
};

// The requests the simulated fake devices have received (all of them).
int requestsReceived();
// Their text, in the order they arrived ("PING 3", "STOP 1"), and a fresh start.
QStringList requestLog();
void clearRequestLog();

// A built family of the tests, and a protocol of it that reaches the fake
// device (another test family builds on these: slotted_family.h); their
// family id is their FamilyParts'.
comm::FamilyInfo builtTestFamily(const QString& title, const QString& defaultProtocol);
comm::ProtocolInfo fakeLineProtocol(const QString& id, const QString& title);

// Every part of the family: family, protocol, simulator and check (comm),
// page (GUI) and command group (CLI).
FamilyParts fakeParts();
// Registers them (registerFamily, as the built-in families are). Safe to
// call more than once.
void registerFakeFamily();

}  // namespace cambench::fake
