// Compax3Drive: the motion sequence of docs/protocols/compax3.md (control word
// 1100.3), each command that moves the axis sent once.
#include "compax3_drive.h"

#include "compax3_syntax.h"

#include "model/compax3/compax3_dictionary.h"

#include <QCoreApplication>

namespace cambench::comm {

Result<Compax3DriveStatus> Compax3Drive::sendControl(quint16 word, const QString& what,
                                                     RetryPolicy retry) {
    const QByteArray command = compax3WriteCommand(kCompax3ControlWord, compax3HexText(word, 4));
    const Status sent = writeCommand(command, retry);
    if (sent) return status();
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

Result<Compax3DriveStatus> Compax3Drive::motion(Compax3Motion motion) {
    const QString what = compax3MotionText(motion);
    switch (motion) {
        case Compax3Motion::Enable: {
            // Off, then on: the rising edge of b0 acknowledges a pending error.
            // Neither moves the axis, and writing either twice is harmless.
            const QByteArray off =
                compax3WriteCommand(kCompax3ControlWord, compax3HexText(compax3control::kOff, 4));
            if (const Status done = writeCommand(off, RetryPolicy::Idempotent); !done)
                return done.error();
            return sendControl(compax3control::kEnable, what, RetryPolicy::Idempotent);
        }
        case Compax3Motion::Disable:
            return sendControl(compax3control::kOff, what, RetryPolicy::Idempotent);
        case Compax3Motion::Stop:
            // A STOP must get through: repeating it only stops again.
            return sendControl(compax3control::kEnable, what, RetryPolicy::Idempotent);
        case Compax3Motion::JogPlus:
            return sendControl(compax3control::kRun | compax3control::kJogPlus, what,
                               RetryPolicy::Never);
        case Compax3Motion::JogMinus:
            return sendControl(compax3control::kRun | compax3control::kJogMinus, what,
                               RetryPolicy::Never);
    }
    return Error::usage(QStringLiteral("unknown motion"));
}

Status Compax3Drive::writeSetValue(const Compax3ObjectId& id, double value) {
    const Result<QString> wire =
        compax3WireValueFor(Compax3Dictionary::builtin(), id, compax3NumberText(value));
    if (!wire) return wire.error();
    return writeObject(id, *wire);
}

Result<Compax3DriveStatus> Compax3Drive::moveSet(const Compax3SetMove& move) {
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
        {move.acceleration, compax3SetDeceleration(move.set)}};
    for (const auto& [value, id] : values)
        if (value) {
            const Result<QString> wire =
                compax3WireValueFor(Compax3Dictionary::builtin(), id, compax3NumberText(*value));
            if (!wire) return wire.error();
        }
    const Result<Compax3DriveStatus> before = status();
    if (!before) return before.error();
    if (before->status.powerless())
        return Error::device(
            0, QCoreApplication::translate(
                   "cambench::comm", "the axis is powerless: enable it first (nothing was sent)"));
    for (const auto& [value, id] : values)
        if (value)
            if (const Status written = writeSetValue(id, *value); !written) return written.error();
    // The set selected without the start bit, then with it: the start is
    // its rising edge.
    const QByteArray select = compax3WriteCommand(
        kCompax3ControlWord, compax3HexText(compax3control::select(move.set), 4));
    if (const Status selected = writeCommand(select, RetryPolicy::Idempotent); !selected)
        return selected.error();
    return sendControl(compax3control::start(move.set), compax3SetMoveText(move),
                       RetryPolicy::Never);
}

}  // namespace cambench::comm
