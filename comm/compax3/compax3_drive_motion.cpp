// Compax3Drive: the motion sequence of docs/protocols/compax3.md (control word
// 1100.3), each command that moves the axis sent once; and the drive as the
// shell's MotionControl (STOP of everything, what moves before quitting).
#include "compax3_drive.h"

#include "compax3_syntax.h"

#include "model/compax3/compax3_dictionary.h"

#include <QCoreApplication>
#include <QScopedValueRollback>

namespace cambench::comm {

namespace {

// The state after an acknowledged command: a failed read is said, and the
// command stays done.
Compax3CommandResult acknowledged(const Result<Compax3DriveStatus>& after) {
    Compax3CommandResult result;
    if (after)
        result.after = *after;
    else
        result.readBackFailed = after.error().message;
    return result;
}

}  // namespace

Result<Compax3CommandResult> Compax3Drive::sendControl(quint16 word, const QString& what,
                                                       RetryPolicy retry) {
    const QByteArray command = compax3WriteCommand(kCompax3ControlWord, compax3HexText(word, 4));
    const Status sent = writeCommand(command, retry);
    if (sent) return acknowledged(status());
    if (sent.error().kind != ErrorKind::Communication || retry != RetryPolicy::Never)
        return sent.error();
    // The answer was lost: the drive may have taken the command. Sending it
    // again could move the axis a second time; read what it does instead.
    const QString lost =
        QCoreApplication::translate("cambench::comm",
                                    "the answer to \"%1\" was lost (%2); it was not sent again, "
                                    "because it moves the axis each time it arrives")
            .arg(what, sent.error().message);
    const Result<Compax3DriveStatus> back = status();
    if (!back)
        return Error::communication(
            QCoreApplication::translate("cambench::comm",
                                        "%1. Reading back failed too (%2): the axis's state is "
                                        "unknown; look at the machine")
                .arg(lost, back.error().message));
    const QString taken =
        back->controlWord == word
            ? QCoreApplication::translate("cambench::comm", "the command was taken")
            : QCoreApplication::translate("cambench::comm",
                                          "the command was not taken (control word %1)")
                  .arg(compax3HexText(back->controlWord, 4));
    return Error::communication(
        QCoreApplication::translate("cambench::comm", "%1. Read back: %2; the axis is %3")
            .arg(lost, taken, back->summary()));
}

Result<Compax3CommandResult> Compax3Drive::enable(const QString& what) {
    // The status first: the acknowledging edge needs power off, and a
    // powered drive (perhaps holding a load) must never lose it here.
    const Result<Compax3DriveStatus> before = status();
    if (!before) return before.error();
    if (!before->status.powerless()) {
        Compax3CommandResult result;
        result.after = *before;
        result.nothingSent = true;
        result.note =
            before->status.noError()
                ? QCoreApplication::translate("cambench::comm",
                                              "the drive is powered already: nothing was sent")
                : QCoreApplication::translate(
                      "cambench::comm",
                      "the drive is powered with an error pending (%1): nothing was sent, "
                      "because acknowledging it drops power; stop the axis, Disable, then "
                      "Enable")
                      .arg(compax3LastErrorText(before->lastError));
        return result;
    }
    // Off, then on: the rising edge of b0 acknowledges a pending error.
    // Neither moves the axis, and writing either twice is harmless.
    const QByteArray off =
        compax3WriteCommand(kCompax3ControlWord, compax3HexText(compax3control::kOff, 4));
    if (const Status done = writeCommand(off, RetryPolicy::Idempotent); !done) return done.error();
    return sendControl(compax3control::kEnable, what, RetryPolicy::Idempotent);
}

Result<Compax3CommandResult> Compax3Drive::motion(Compax3Motion motion) {
    const QScopedValueRollback<bool> stopping(m_stopping,
                                              m_stopping || motion == Compax3Motion::Stop);
    const QString what = compax3MotionText(motion);
    switch (motion) {
        case Compax3Motion::Enable:
            return enable(what);
        case Compax3Motion::Disable:
            return sendControl(compax3control::kOff, what, RetryPolicy::Idempotent);
        case Compax3Motion::Stop:
            return stop(what);
        case Compax3Motion::JogPlus:
            return sendControl(compax3control::kRun | compax3control::kJogPlus, what,
                               RetryPolicy::Never);
        case Compax3Motion::JogMinus:
            return sendControl(compax3control::kRun | compax3control::kJogMinus, what,
                               RetryPolicy::Never);
    }
    return Error::usage(QStringLiteral("unknown motion"));
}

Result<Compax3SetValues> Compax3Drive::readSet(int set) {
    if (set < 0 || set > kCompax3LastSetNumber)
        return Error::usage(
            QCoreApplication::translate("cambench::comm", "the set must be 0 to %1, not %2")
                .arg(kCompax3LastSetNumber)
                .arg(set));
    Compax3SetValues values;
    values.set = set;
    const std::pair<Compax3ObjectId, double*> numbers[] = {
        {compax3SetTarget(set), &values.target},
        {compax3SetVelocity(set), &values.velocity},
        {compax3SetAcceleration(set), &values.acceleration},
        {compax3SetDeceleration(set), &values.deceleration}};
    for (const auto& [id, into] : numbers) {
        const Result<double> value = readNumber(id);
        if (!value) return value.error();
        *into = *value;
    }
    const Result<double> mode = readNumber(compax3SetMode(set));
    if (!mode) return mode.error();
    values.mode = int(*mode);
    values.readAt = QDateTime::currentDateTime();
    return values;
}

Result<Compax3CommandResult> Compax3Drive::moveSet(const Compax3SetMove& move) {
    if (move.set < 0 || move.set > kCompax3LastSetNumber)
        return Error::usage(
            QCoreApplication::translate("cambench::comm", "the set must be 0 to %1, not %2")
                .arg(kCompax3LastSetNumber)
                .arg(move.set));
    // Every value checked before the first byte.
    const std::pair<std::optional<double>, Compax3ObjectId> values[] = {
        {move.target, compax3SetTarget(move.set)},
        {move.velocity, compax3SetVelocity(move.set)},
        {move.acceleration, compax3SetAcceleration(move.set)},
        {move.deceleration, compax3SetDeceleration(move.set)}};
    QList<std::pair<Compax3ObjectId, QString>> wires;
    for (const auto& [value, id] : values)
        if (value) {
            const Result<QString> wire =
                compax3WireValueFor(Compax3Dictionary::builtin(), id, compax3NumberText(*value));
            if (!wire) return wire.error();
            wires.append({id, *wire});
        }
    if (move.shown) {
        // What the person confirmed, checked against the drive before
        // anything is written: a value changed meanwhile (another page, the
        // drive's own program) is no start they agreed to.
        const Result<Compax3SetValues> now = readSet(move.set);
        if (!now) return now.error();
        if (!move.shown->changesTo(*now).isEmpty()) {
            Compax3CommandResult changed;
            changed.nothingSent = true;
            changed.changedSet = *now;
            changed.note = QCoreApplication::translate(
                               "cambench::comm",
                               "set %1 changed on the drive since it was read at %2 (%3): "
                               "nothing was sent")
                               .arg(move.set)
                               .arg(move.shown->readAt.toString(QStringLiteral("HH:mm:ss")),
                                    move.shown->changesTo(*now).join(QStringLiteral(", ")));
            return changed;
        }
    }
    const Result<Compax3DriveStatus> before = status();
    if (!before) return before.error();
    if (before->status.powerless())
        return Error::device(
            0, QCoreApplication::translate(
                   "cambench::comm", "the axis is powerless: enable it first (nothing was sent)"));
    // Only what the drive does not hold already is written.
    for (const auto& [id, wire] : wires) {
        const Result<QString> held = readObject(id, false);
        if (held && compax3SameValue(*held, wire)) continue;
        if (const Status written = writeObject(id, wire); !written) return written.error();
    }
    // The set selected without the start bit, then with it: the start is
    // its rising edge.
    const QByteArray select = compax3WriteCommand(
        kCompax3ControlWord, compax3HexText(compax3control::select(move.set), 4));
    if (const Status selected = writeCommand(select, RetryPolicy::Idempotent); !selected)
        return selected.error();
    return sendControl(compax3control::start(move.set), compax3SetMoveText(move),
                       RetryPolicy::Never);
}

QString Compax3Drive::driveName() const {
    return m_backend.address() < 0
               ? QCoreApplication::translate("cambench::comm", "Compax3 drive")
               : QCoreApplication::translate("cambench::comm", "Compax3 drive at address %1")
                     .arg(m_backend.address());
}

MotionStopReport Compax3Drive::stopAllMotion() {
    // One drive, one axis: the Motion page's STOP (compax3_drive_stop.cpp).
    MotionStopLine line;
    line.what = driveName();
    const Result<Compax3CommandResult> stopped = motion(Compax3Motion::Stop);
    line.nothingToStop = stopped && stopped->nothingSent;
    line.acknowledged = stopped.ok() && !line.nothingToStop;
    line.detail = !stopped ? stopped.error().message
                  : stopped->note.isEmpty() || line.nothingToStop
                      ? stopped->summary()
                      : QStringLiteral("%1; %2").arg(stopped->note, stopped->summary());
    MotionStopReport report;
    report.lines << line;
    return report;
}

Result<QStringList> Compax3Drive::activeMotion() {
    // The status word's number and bits are a public client's, not Parker's
    // manual's (reading C2): what they say is shown as read that way, and
    // "nothing moves" read through them is no fact to leave a drive on.
    const Result<Compax3DriveStatus> now = status();
    if (!now) return now.error();
    if (now->moving())
        return QStringList{
            QCoreApplication::translate(
                "cambench::comm",
                "%1: the axis moves (%2, as read through provisional object numbers)")
                .arg(driveName(), now->summary())};
    if (!now->status.powerless())
        return QStringList{
            QCoreApplication::translate(
                "cambench::comm",
                "%1: the axis is powered (as read through provisional object numbers)")
                .arg(driveName())};
    return Error::communication(
        QCoreApplication::translate(
            "cambench::comm",
            "%1 reads as %2, but through the status word 1000.3, whose number and bits are "
            "provisional (a public client's, not Parker's manual's): whether the axis stands "
            "cannot be told from it")
            .arg(driveName(), now->summary()));
}

}  // namespace cambench::comm
