#pragma once

#include "mc1_address.h"
#include "mc1_parameters.h"
#include "mc1_variant.h"

#include "comm/device/device_connection.h"
#include "model/mc1/mc1_family_id.h"
#include "model/result.h"

#include <QByteArray>
#include <QList>
#include <QStringList>

#include <optional>

namespace cambench::comm {

// What a connected MC100/MC200 can do beyond variables, flags and I/O,
// which every variant has.
enum class Mc1Capability {
    BlockRead,       // RDBLOCK: up to 56 RAM bytes a telegram (MC100 V2)
    MemoryRead,      // RDMEM (MC200 V2), RDMEM6 (MC200 V1: 6 bytes a telegram)
    MemoryWrite,     // WRMEM (MC200 V2)
    ProgramControl,  // SYSDATA: status, start, stop, step, reset, flash (MC200 V2)
    Axes,            // AXIS_NODATA/AXIS_DATA and the axis parameters (MC200 V2)
};

// The PLC program's state (SYSDATA status, manual table 39).
struct Mc1ProgramStatus {
    quint8 flags = 0;
    quint16 programCounter = 0;
    bool present() const { return flags & 0x01; }
    bool running() const { return flags & 0x02; }
    // Each set bit of `flags` as a person reads it ("PLC program running").
    QStringList flagTexts() const;
    // "running, PC 0x1234" / "stopped, PC 0x0000" / "no PLC program".
    QString summary() const;
};

enum class Mc1ProgramCommand { Start, Stop, Step, Reset, FlashSave, FlashLoad };
// "start the PLC program", for messages.
QString mc1ProgramCommandText(Mc1ProgramCommand command);

// One axis as the controller reports it, read through a parameter table
// (mc1_parameters.h).
struct Mc1AxisState {
    int axis = 1;
    qint32 position = 0;
    qint32 target = 0;
    bool moving = false;
    bool homed = false;
    bool error = false;
    // Read through CamBench's guessed parameter numbers: not a fact.
    bool provisional = false;
    // "axis 1 is moving to 100 (now at 12)" / "axis 1 stands at 0", with
    // " (provisional parameter numbers)" when provisional.
    QString summary() const;
};

// What an acknowledged command left on the controller: it is done (the
// controller acknowledged it); `after` is what reading back found, or
// `readBackProblem` says why that read failed, which never makes the
// command a failure.
template <class T>
struct Mc1Done {
    std::optional<T> after;
    QString readBackProblem;
};
using Mc1AxisDone = Mc1Done<Mc1AxisState>;
// The outcome of an acknowledged command from what reading back gave.
template <class T>
Mc1Done<T> mc1Done(const Result<T>& after) {
    Mc1Done<T> done;
    if (after)
        done.after = *after;
    else
        done.readBackProblem = after.error().message;
    return done;
}

// The axes a controller has and how that is known.
struct Mc1Axes {
    QList<int> numbers;  // logical axes, ascending
    QString source;      // "found with RDTABLE", "as given", ...
};
// "1,2,5" (the CLI's --axes, the connection setting): refused naming what
// is wrong; duplicates and order do not matter.
Result<QList<int>> parseMc1AxisList(const QString& text);

enum class Mc1AxisCommand {
    Home,
    MoveAbsolute,  // to `value`
    MoveRelative,  // by `value`
    JogPlus,       // continuous, until stopped
    JogMinus,
    Stop,       // with the programmed ramp
    QuickStop,  // with the maximum ramp
    AcknowledgeError,
    SetSpeed,  // `value` units per second
};
// "move axis 1 by 100", for confirmations and messages.
QString mc1AxisCommandText(int axis, Mc1AxisCommand command, qint32 value);
// Whether the command sets an axis in motion (and so wants a confirmation).
bool mc1AxisCommandMoves(Mc1AxisCommand command);

// Whether `point` can be written on `variant`: refused naming it when it is
// an input or a number the variant lacks. Nothing is sent.
Status mc1CheckWritable(const Mc1Point& point, Mc1Variant variant);

// An acting command whose answer was lost and which was therefore not sent
// again: the error says what reading back found.
Error mc1LostAnswer(const QString& what, const Error& error, const QString& readBack);

// "0x1000: 0a 0b ..." lines of 16 bytes, for memory shown to a person.
QString mc1HexLines(int address, const QByteArray& bytes);

// A connected MICRO DESIGN MC100/MC200 controller. Every call identifies
// the controller first if that has not happened yet (the variant probed,
// or the one the settings name checked against what answers). Commands
// that act are sent once: when their answer is lost the state is read
// back and the error says what was found.
class Mc1Device : public DeviceConnection {
public:
    QString familyId() const override { return mc1FamilyId; }

    // The variant in use (after identification; before it, the settings').
    virtual Mc1Variant variant() const = 0;
    // How the variant was found: "probed" or "as given (the probe found
    // MC200 V1)".
    virtual QString variantSource() const = 0;
    virtual Result<Mc1Variant> ensureIdentified() = 0;
    virtual bool has(Mc1Capability capability) const = 0;
    // The protocol offers no serial number. What tells two controllers
    // apart: the variant ("variant": "mc200v2"); over the binary protocol
    // on an MC200 also the axis table RDTABLE answers ("axes": "1:0/1 2:1/1",
    // logical axis: physical coding/type) and, on an MC200 V2, where its
    // PLC program's data block starts ("program udb": SYSDATA 08, which
    // moves with the program loaded; provisional, comm/mc1/README.md).
    Result<DeviceIdentity> readIdentity() override;

    // Variables, signed, of the variant's width (24 or 32 bits).
    virtual Result<qint64> readVariable(int number) = 0;
    // Refused before sending when `value` does not fit the width.
    virtual Status writeVariable(int number, qint64 value) = 0;

    // Flags, inputs and outputs by their manual numbers, in the given order.
    virtual Result<QList<bool>> readPoints(const QList<Mc1Point>& points,
                                           const ProgressFn& progress = {}) = 0;
    // Sets or clears one flag or output (WRBIT) and returns the value read
    // back afterwards.
    virtual Result<bool> writePoint(const Mc1Point& point, bool on) = 0;
    // The raw bytes of an external RAM page (the flags' page for a backup).
    virtual Result<QByteArray> readExternalPage(quint8 page, const ProgressFn& progress = {}) = 0;

    virtual Result<Mc1ProgramStatus> programStatus() = 0;
    // Acknowledged: done, with the status read after it (or why that read
    // failed, which never makes the command a failure).
    virtual Result<Mc1Done<Mc1ProgramStatus>> programCommand(Mc1ProgramCommand command) = 0;

    // The axes the controller has: on an MC200 V2 each logical axis
    // RDTABLE answers for (once, then kept), or the ones given with
    // setGivenAxes; none where the variant has no axis telegrams.
    virtual Result<Mc1Axes> axes() = 0;
    virtual Result<Mc1AxisState> axisState(int axis) = 0;
    // One value of an axis read (RDSTAT) through the parameter table in
    // use, nothing else: a refusal names the parameter's number.
    virtual Result<qint32> axisValue(int axis, Mc1AxisValue value) = 0;
    // Acknowledged: done, with the axis as read after it (or why that read
    // failed). A refusal is an error; a lost answer too, saying what
    // reading back found (an acting command is not sent again).
    virtual Result<Mc1AxisDone> axisCommand(int axis, Mc1AxisCommand command, qint32 value = 0) = 0;

    // The axes to use instead of finding them (none: find them).
    void setGivenAxes(const std::optional<QList<int>>& axes) { m_givenAxes = axes; }
    const std::optional<QList<int>>& givenAxes() const { return m_givenAxes; }
    // The RDSTAT parameter numbers of the axes' values; the provisional
    // built-in table until the controller's own is set.
    void setAxisParameters(const Mc1AxisParameterTable& table) { m_parameters = table; }
    const Mc1AxisParameterTable& axisParameters() const { return m_parameters; }

    virtual Result<QByteArray> readMemory(int address, int length,
                                          const ProgressFn& progress = {}) = 0;
    virtual Status writeMemory(int address, const QByteArray& bytes,
                               const ProgressFn& progress = {}) = 0;

private:
    std::optional<QList<int>> m_givenAxes;
    Mc1AxisParameterTable m_parameters = mc1ProvisionalAxisParameters();
};

}  // namespace cambench::comm
