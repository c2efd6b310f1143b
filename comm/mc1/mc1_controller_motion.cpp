// Mc1Controller: the PLC program, the axes and the memory (MC200).
#include "mc1_controller.h"

#include "mc1_parameters.h"

#include <QCoreApplication>

namespace cambench::comm {

namespace {

// The telegram and its command byte for each axis command.
struct AxisTelegram {
    Mc1Op op;
    quint8 command;
    bool withValue;
};

AxisTelegram axisTelegram(Mc1AxisCommand command) {
    switch (command) {
        case Mc1AxisCommand::Home:
            return {Mc1Op::AxisCommand, 0x06, false};
        case Mc1AxisCommand::MoveAbsolute:
            return {Mc1Op::AxisDataCommand, 0x03, true};
        case Mc1AxisCommand::MoveRelative:
            return {Mc1Op::AxisDataCommand, 0x04, true};
        case Mc1AxisCommand::JogPlus:
        case Mc1AxisCommand::JogMinus:
            return {Mc1Op::AxisDataCommand, 0x05, true};
        case Mc1AxisCommand::Stop:
            return {Mc1Op::AxisCommand, 0x08, false};
        case Mc1AxisCommand::QuickStop:
            return {Mc1Op::AxisCommand, 0x09, false};
        case Mc1AxisCommand::AcknowledgeError:
            return {Mc1Op::AxisCommand, 0x11, false};
        case Mc1AxisCommand::SetSpeed:
            return {Mc1Op::AxisDataCommand, 0x0C, true};
    }
    return {Mc1Op::AxisCommand, 0x08, false};
}

}  // namespace

Result<Mc1ProgramStatus> Mc1Controller::programStatus() {
    if (const Status ok =
            require(Mc1Capability::ProgramControl,
                    QCoreApplication::translate("cambench::comm", "report its program status"));
        !ok)
        return ok.error();
    const Result<QByteArray> answer = m_link.exchange(Mc1Op::ProgramStatus, {});
    if (!answer) return answer.error();
    Mc1ProgramStatus status;
    status.flags = quint8(answer->at(0));
    status.programCounter = quint16(mc1FromLittleEndian(answer->mid(1, 2), false));
    return status;
}

Result<Mc1Done<Mc1ProgramStatus>> Mc1Controller::programCommand(Mc1ProgramCommand command) {
    const QString what = mc1ProgramCommandText(command);
    if (const Status ok = require(Mc1Capability::ProgramControl, what); !ok) return ok.error();
    Result<QByteArray> done = QByteArray();
    switch (command) {
        case Mc1ProgramCommand::Start:
            done = m_link.exchange(Mc1Op::ProgramStart, {});
            break;
        case Mc1ProgramCommand::Stop:
            done = m_link.exchange(Mc1Op::ProgramStop, {});
            break;
        case Mc1ProgramCommand::Step:
            done = m_link.exchange(Mc1Op::ProgramStep, {});
            break;
        case Mc1ProgramCommand::Reset:
            // Parameter 0: the PLC program starts again, nothing is wiped.
            done = m_link.exchange(Mc1Op::Reset, mc1LittleEndian(0, 1));
            break;
        case Mc1ProgramCommand::FlashSave:
        case Mc1ProgramCommand::FlashLoad:
            done = m_link.exchange(
                Mc1Op::Flash, mc1LittleEndian(command == Mc1ProgramCommand::FlashSave ? 1 : 2, 1));
            break;
    }
    const Result<Mc1ProgramStatus> after = programStatus();
    if (!done) {
        if (done.error().kind != ErrorKind::Communication) return done.error();
        return mc1LostAnswer(what, done.error(),
                             after ? QCoreApplication::translate("cambench::comm", "PLC program %1")
                                         .arg(after->summary())
                                   : QCoreApplication::translate(
                                         "cambench::comm", "reading the status failed too: %1")
                                         .arg(after.error().message));
    }
    return mc1Done(after);
}

Status Mc1Controller::checkAxisNumber(int axis) const {
    if (axis >= kMc1FirstAxis && axis <= kMc1LastAxis) return success();
    return Error::usage(QCoreApplication::translate("cambench::comm", "axes are %1 to %2, not %3")
                            .arg(kMc1FirstAxis)
                            .arg(kMc1LastAxis)
                            .arg(axis));
}

Result<QList<int>> Mc1Controller::findAxes() {
    // RDTABLE (manual 3.12) gives a logical axis's physical coding 0-7 and
    // its module's type; an axis the controller lacks is refused (NAK).
    QList<int> found;
    for (int axis = kMc1FirstAxis; axis <= kMc1LastAxis; ++axis) {
        const Result<QByteArray> entry = m_link.exchange(
            Mc1Op::ReadTable, QByteArray(2, '\0') + mc1LittleEndian(axis, 1) + QByteArray(1, '\0'));
        if (entry) {
            if (!entry->isEmpty() && quint8(entry->at(0)) <= 7) found << axis;
            continue;
        }
        if (!isMc1Refusal(entry.error())) return entry.error();
    }
    return found;
}

std::optional<Mc1Axes> Mc1Controller::knownAxes() const {
    if (givenAxes())
        return Mc1Axes{*givenAxes(), QCoreApplication::translate("cambench::comm", "as given")};
    return m_found;
}

Result<Mc1Axes> Mc1Controller::axes() {
    if (const std::optional<Mc1Axes> known = knownAxes()) return *known;
    const Result<Mc1Variant> identified = ensureIdentified();
    if (!identified) return identified.error();
    if (!has(Mc1Capability::Axes))
        return Mc1Axes{
            {},
            QCoreApplication::translate(
                "cambench::comm", "none: the %1 has no axis telegrams (they need an MC200 V2)")
                .arg(mc1VariantName(*identified))};
    const Result<QList<int>> found = findAxes();
    if (!found) return found.error();
    m_found = Mc1Axes{*found, QCoreApplication::translate("cambench::comm", "found with RDTABLE")};
    return *m_found;
}

Result<qint32> Mc1Controller::readAxisValue(int axis, Mc1AxisValue value) {
    const Mc1AxisParameterTable& table = axisParameters();
    const std::optional<quint16> number = table.number(axis, value);
    if (!number)
        return Error::usage(QCoreApplication::translate(
                                "cambench::comm",
                                "the parameter table (%1) names no %2 parameter for axis %3: "
                                "load a table that names it")
                                .arg(table.source, mc1AxisValueName(value))
                                .arg(axis));
    const Result<QByteArray> answer =
        m_link.exchange(Mc1Op::ReadStatus, mc1LittleEndian(*number, 2));
    if (answer) return qint32(mc1FromLittleEndian(*answer, true));
    if (!isMc1Refusal(answer.error())) return answer.error();
    const QString refused =
        QCoreApplication::translate("cambench::comm",
                                    "the controller refused RDSTAT of parameter %1 (0x%2), the %3 "
                                    "of axis %4")
            .arg(*number)
            .arg(*number, 4, 16, QLatin1Char('0'))
            .arg(mc1AxisValueName(value))
            .arg(axis);
    return Error::device(
        kMc1Nak,
        table.provisional
            ? QCoreApplication::translate(
                  "cambench::comm",
                  "%1: that number is CamBench's guess, not the controller's; load the "
                  "controller's parameter table (name,axis,parameter; --parameters FILE, or Load "
                  "parameter table… on the Axes page)")
                  .arg(refused)
            : QCoreApplication::translate("cambench::comm", "%1: check the parameter table %2")
                  .arg(refused, table.source));
}

Status Mc1Controller::canReadAxis(int axis) {
    if (const Status ok = require(Mc1Capability::Axes,
                                  QCoreApplication::translate("cambench::comm", "report its axes"));
        !ok)
        return ok.error();
    return checkAxisNumber(axis);
}

Result<qint32> Mc1Controller::axisValue(int axis, Mc1AxisValue value) {
    if (const Status ok = canReadAxis(axis); !ok) return ok.error();
    return readAxisValue(axis, value);
}

Status Mc1Controller::checkAxisExists(int axis, const Mc1Axes& present) const {
    if (present.numbers.contains(axis)) return success();
    QStringList numbers;
    for (int n : present.numbers) numbers << QString::number(n);
    return Error::usage(QCoreApplication::translate(
                            "cambench::comm", "the controller has no axis %1: its axes are %2 (%3)")
                            .arg(axis)
                            .arg(numbers.isEmpty()
                                     ? QCoreApplication::translate("cambench::comm", "none")
                                     : numbers.join(QStringLiteral(", ")),
                                 present.source));
}

Result<Mc1AxisState> Mc1Controller::axisState(int axis) {
    if (const Status ok = canReadAxis(axis); !ok) return ok.error();
    // Where the axes are known already, one it lacks is not asked for (a
    // read never starts the search: a STOP reads back while it may fail).
    const std::optional<Mc1Axes> known = knownAxes();
    if (known)
        if (const Status ok = checkAxisExists(axis, *known); !ok) return ok.error();
    qint32 values[3] = {};
    const Mc1AxisValue which[3] = {Mc1AxisValue::Position, Mc1AxisValue::Target,
                                   Mc1AxisValue::Status};
    for (int i = 0; i < 3; ++i) {
        const Result<qint32> value = readAxisValue(axis, which[i]);
        if (!value) return value.error();
        values[i] = *value;
    }
    Mc1AxisState state;
    state.axis = axis;
    state.position = values[0];
    state.target = values[1];
    state.moving = values[2] & kMc1AxisMoving;
    state.homed = values[2] & kMc1AxisHomed;
    state.error = values[2] & kMc1AxisError;
    state.provisional = axisParameters().provisional;
    return state;
}

Mc1Retry mc1AxisCommandRetry(Mc1AxisCommand command) {
    const AxisTelegram telegram = axisTelegram(command);
    return mc1AxisRetry(telegram.op, telegram.command);
}

Status Mc1Controller::sendAxisCommand(int axis, Mc1AxisCommand command, qint32 value,
                                      int maxAttempts) {
    const QString what = mc1AxisCommandText(axis, command, value);
    const bool stop = command == Mc1AxisCommand::Stop || command == Mc1AxisCommand::QuickStop;
    if (!stop || m_identified)
        if (const Status ok = require(Mc1Capability::Axes, what); !ok) return ok.error();
    if (const Status ok = checkAxisNumber(axis); !ok) return ok.error();
    if (command == Mc1AxisCommand::SetSpeed && value <= 0)
        return Error::usage(
            QCoreApplication::translate("cambench::comm", "a speed must be more than 0, not %1")
                .arg(value));
    const AxisTelegram telegram = axisTelegram(command);
    QByteArray parameters = mc1LittleEndian(axis, 1) + mc1LittleEndian(telegram.command, 1);
    if (command == Mc1AxisCommand::JogPlus || command == Mc1AxisCommand::JogMinus)
        value = command == Mc1AxisCommand::JogPlus ? 1 : 0;
    if (telegram.withValue) parameters += mc1LittleEndian(value, 4);
    const Result<QByteArray> done = m_link.exchange(telegram.op, parameters, maxAttempts);
    if (!done) return done.error();
    return success();
}

Result<Mc1AxisDone> Mc1Controller::axisCommand(int axis, Mc1AxisCommand command, qint32 value) {
    const QString what = mc1AxisCommandText(axis, command, value);
    if (const Status ok = require(Mc1Capability::Axes, what); !ok) return ok.error();
    if (const Status ok = checkAxisNumber(axis); !ok) return ok.error();
    // Checked before the first byte: an axis the controller lacks gets nothing.
    const Result<Mc1Axes> present = axes();
    if (!present) return present.error();
    if (const Status ok = checkAxisExists(axis, *present); !ok) return ok.error();
    const Status done = sendAxisCommand(axis, command, value);
    const Result<Mc1AxisState> after = axisState(axis);
    if (!done) {
        if (done.error().kind != ErrorKind::Communication) return done.error();
        const QString found =
            after ? (mc1AxisCommandMoves(command)
                         ? QCoreApplication::translate("cambench::comm",
                                                       "the move may have started: %1")
                         : QStringLiteral("%1"))
                        .arg(after->summary())
                  : QCoreApplication::translate("cambench::comm", "reading the axis failed too: %1")
                        .arg(after.error().message);
        if (mc1AxisCommandRetry(command) != Mc1Retry::Never)
            return Error::communication(
                QCoreApplication::translate("cambench::comm",
                                            "no answer to \"%1\" (%2). Read back: %3")
                    .arg(what, done.error().message, found));
        return mc1LostAnswer(what, done.error(), found);
    }
    return mc1Done(after);
}

MotionControl* Mc1Controller::motionControl() {
    // Not identified: a STOP that may be refused is better than none (or
    // than a probe before it), unless the settings name a variant without
    // axis telegrams.
    if (!m_identified) return !m_given || *m_given == Mc1Variant::Mc200V2 ? &m_motion : nullptr;
    return has(Mc1Capability::Axes) ? &m_motion : nullptr;
}

Result<QByteArray> Mc1Controller::readMemory(int address, int length, const ProgressFn& progress) {
    if (const Status ok = require(Mc1Capability::MemoryRead,
                                  QCoreApplication::translate("cambench::comm", "read memory"));
        !ok)
        return ok.error();
    if (address < 0 || length < 1 || address + length > kMc1MemorySize)
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "memory is 0x0000 to 0xFFFF: %1 bytes from 0x%2 do not fit")
                .arg(length)
                .arg(address, 4, 16, QLatin1Char('0')));
    const bool wide = has(Mc1Capability::MemoryWrite);  // RDMEM; an MC200 V1 has RDMEM6
    QByteArray bytes;
    while (bytes.size() < length) {
        const int at = address + int(bytes.size());
        const int n = std::min<int>(wide ? kMc1MaxMemoryRead : 6, length - int(bytes.size()));
        const Result<QByteArray> got =
            wide
                ? m_link.exchange(Mc1Op::ReadMemory, mc1LittleEndian(at, 2) + mc1LittleEndian(n, 1))
                : m_link.exchange(Mc1Op::ReadMemory6, mc1LittleEndian(at, 2));
        if (!got) return got.error();
        bytes += got->left(n);
        if (progress) progress(bytes.size(), length);
    }
    return bytes;
}

Status Mc1Controller::writeMemory(int address, const QByteArray& bytes,
                                  const ProgressFn& progress) {
    if (const Status ok = require(Mc1Capability::MemoryWrite,
                                  QCoreApplication::translate("cambench::comm", "write memory"));
        !ok)
        return ok.error();
    if (address < 0 || bytes.isEmpty() || address + bytes.size() > kMc1MemorySize)
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "memory is 0x0000 to 0xFFFF: %1 bytes from 0x%2 do not fit")
                .arg(bytes.size())
                .arg(address, 4, 16, QLatin1Char('0')));
    for (qsizetype done = 0; done < bytes.size();) {
        const QByteArray chunk = bytes.mid(done, kMc1MaxMemoryWrite);
        const Result<QByteArray> written =
            m_link.exchange(Mc1Op::WriteMemory, mc1LittleEndian(address + done, 2) +
                                                    mc1LittleEndian(chunk.size(), 1) + chunk);
        if (!written) return written.error();
        done += chunk.size();
        if (progress) progress(done, bytes.size());
    }
    return success();
}

}  // namespace cambench::comm
