#include "mc1_device.h"

#include <QCoreApplication>

#include <algorithm>

namespace cambench::comm {

QStringList Mc1ProgramStatus::flagTexts() const {
    // Manual table 39, bit by bit.
    static const char* const kBits[] = {
        QT_TRANSLATE_NOOP("cambench::comm", "PLC program present"),
        QT_TRANSLATE_NOOP("cambench::comm", "PLC program running"),
        QT_TRANSLATE_NOOP("cambench::comm", "error: invalid opcode"),
        QT_TRANSLATE_NOOP("cambench::comm", "error: stack overflow"),
        QT_TRANSLATE_NOOP("cambench::comm", "breakpoint list cleared"),
        QT_TRANSLATE_NOOP("cambench::comm", "task switching off"),
        QT_TRANSLATE_NOOP("cambench::comm", "current bit result 1"),
        QT_TRANSLATE_NOOP("cambench::comm", "PLC program at a breakpoint"),
    };
    QStringList texts;
    for (int bit = 0; bit < 8; ++bit)
        if (flags & (1u << bit)) texts << QCoreApplication::translate("cambench::comm", kBits[bit]);
    return texts;
}

QString Mc1ProgramStatus::summary() const {
    if (!present()) return QCoreApplication::translate("cambench::comm", "no PLC program");
    const QString pc = QStringLiteral("0x%1").arg(programCounter, 4, 16, QLatin1Char('0'));
    return (running() ? QCoreApplication::translate("cambench::comm", "running, PC %1")
                      : QCoreApplication::translate("cambench::comm", "stopped, PC %1"))
        .arg(pc);
}

QString mc1ProgramCommandText(Mc1ProgramCommand command) {
    switch (command) {
        case Mc1ProgramCommand::Start:
            return QCoreApplication::translate("cambench::comm", "start the PLC program");
        case Mc1ProgramCommand::Stop:
            return QCoreApplication::translate("cambench::comm", "stop the PLC program");
        case Mc1ProgramCommand::Step:
            return QCoreApplication::translate("cambench::comm", "run one step of the PLC program");
        case Mc1ProgramCommand::Reset:
            return QCoreApplication::translate("cambench::comm", "reset the controller");
        case Mc1ProgramCommand::FlashSave:
            return QCoreApplication::translate("cambench::comm", "save to flash");
        case Mc1ProgramCommand::FlashLoad:
            return QCoreApplication::translate("cambench::comm", "load from flash");
    }
    return {};
}

QString Mc1AxisState::summary() const {
    QString text = moving ? QCoreApplication::translate("cambench::comm",
                                                        "axis %1 is moving to %2 (now at %3)")
                                .arg(axis)
                                .arg(target)
                                .arg(position)
                          : QCoreApplication::translate("cambench::comm", "axis %1 stands at %2")
                                .arg(axis)
                                .arg(position);
    if (error) text += QCoreApplication::translate("cambench::comm", ", axis error");
    if (provisional)
        text += QCoreApplication::translate("cambench::comm", " (provisional parameter numbers)");
    return text;
}

Result<QList<int>> parseMc1AxisList(const QString& text) {
    QList<int> axes;
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        bool ok = false;
        const int axis = part.trimmed().toInt(&ok);
        if (!ok || axis < kMc1FirstAxis || axis > kMc1LastAxis)
            return Error::usage(QCoreApplication::translate(
                                    "cambench::comm",
                                    "axes are numbers %1 to %2 separated by commas (1,2,5); "
                                    "\"%3\" is not one")
                                    .arg(kMc1FirstAxis)
                                    .arg(kMc1LastAxis)
                                    .arg(part.trimmed()));
        if (!axes.contains(axis)) axes << axis;
    }
    if (axes.isEmpty())
        return Error::usage(
            QCoreApplication::translate("cambench::comm", "no axis given: name them like 1,2,5"));
    std::sort(axes.begin(), axes.end());
    return axes;
}

QString mc1AxisCommandText(int axis, Mc1AxisCommand command, qint32 value) {
    switch (command) {
        case Mc1AxisCommand::Home:
            return QCoreApplication::translate("cambench::comm", "home axis %1").arg(axis);
        case Mc1AxisCommand::MoveAbsolute:
            return QCoreApplication::translate("cambench::comm", "move axis %1 to %2")
                .arg(axis)
                .arg(value);
        case Mc1AxisCommand::MoveRelative:
            return QCoreApplication::translate("cambench::comm", "move axis %1 by %2")
                .arg(axis)
                .arg(value);
        case Mc1AxisCommand::JogPlus:
            return QCoreApplication::translate("cambench::comm",
                                               "move axis %1 continuously in the plus direction")
                .arg(axis);
        case Mc1AxisCommand::JogMinus:
            return QCoreApplication::translate("cambench::comm",
                                               "move axis %1 continuously in the minus direction")
                .arg(axis);
        case Mc1AxisCommand::Stop:
            return QCoreApplication::translate("cambench::comm", "stop axis %1").arg(axis);
        case Mc1AxisCommand::QuickStop:
            return QCoreApplication::translate("cambench::comm",
                                               "stop axis %1 with the maximum ramp")
                .arg(axis);
        case Mc1AxisCommand::AcknowledgeError:
            return QCoreApplication::translate("cambench::comm", "acknowledge the error of axis %1")
                .arg(axis);
        case Mc1AxisCommand::SetSpeed:
            return QCoreApplication::translate("cambench::comm", "set the speed of axis %1 to %2")
                .arg(axis)
                .arg(value);
    }
    return {};
}

Result<DeviceIdentity> Mc1Device::readIdentity() {
    const Result<Mc1Variant> identified = ensureIdentified();
    if (!identified) return identified.error();
    DeviceIdentity identity;
    identity.set(QStringLiteral("variant"), mc1VariantKey(*identified));
    return identity;
}

Status mc1CheckWritable(const Mc1Point& point, Mc1Variant variant) {
    if (point.area == Mc1Area::Input)
        return Error::usage(
            QCoreApplication::translate("cambench::comm", "%1 is an input: inputs are read-only")
                .arg(mc1PointText(point)));
    const Result<Mc1BitAddress> address = mc1BitAddress(point, isMc200(variant));
    if (!address) return address.error();
    return success();
}

Error mc1LostAnswer(const QString& what, const Error& error, const QString& readBack) {
    return Error::communication(
        QCoreApplication::translate(
            "cambench::comm",
            "the answer to \"%1\" was lost (%2); it was not sent again, because it acts each time "
            "it arrives. Read back: %3")
            .arg(what, error.message, readBack));
}

QString mc1HexLines(int address, const QByteArray& bytes) {
    QString text;
    for (int at = 0; at < bytes.size(); at += 16)
        text += QStringLiteral("0x%1: %2\n")
                    .arg(QString::number(address + at, 16).toUpper().rightJustified(4, u'0'),
                         QString::fromLatin1(bytes.mid(at, 16).toHex(' ')));
    return text;
}

bool mc1AxisCommandMoves(Mc1AxisCommand command) {
    switch (command) {
        case Mc1AxisCommand::Home:
        case Mc1AxisCommand::MoveAbsolute:
        case Mc1AxisCommand::MoveRelative:
        case Mc1AxisCommand::JogPlus:
        case Mc1AxisCommand::JogMinus:
            return true;
        default:
            return false;
    }
}

}  // namespace cambench::comm
