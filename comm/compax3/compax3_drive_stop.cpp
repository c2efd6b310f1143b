// Compax3Drive's STOP: it changes nothing but motion (issue 35 item 2;
// docs/protocols/compax3.md, "STOP").
//
// The control word's b0 powers the drive, and its rising edge acknowledges a
// pending error (reading C3). A STOP word that keeps power must hold b0 at 1
// ($0001: the stop bits cleared); written to a drive whose b0 is 0 that is
// a rising edge: it would power a drive someone switched off and
// acknowledge its error. So the STOP reads the status word first (one short
// read, about 1 ms at 115200 baud) and then:
// - powered: $0001. A powered drive holds b0 = 1 (power needs it), so this
//   is no edge: the axis stops with its ramp and keeps power.
// - powerless: nothing is written; nothing there can move.
// - the status could not be read: $0000. The only word that can never be
//   a rising edge has b0 = 0; it stops the axis by dropping its power (a
//   powered one coasts or is held by its brake, as the drive is set).
//   Neither other choice is safe: $0001 could power a drive in error, and
//   writing nothing leaves a moving axis moving. The result says so.
#include "compax3_drive.h"

#include <QCoreApplication>

namespace cambench::comm {

namespace {

// A damaged answer gets one more read; a silent drive is not waited for
// twice more (each silent attempt waits the late-answer window).
constexpr int kStatusAttempts = 2;

}  // namespace

Result<Compax3CommandResult> Compax3Drive::stop(const QString& what) {
    const Result<double> word = readNumber(kCompax3StatusWord, kStatusAttempts);
    if (!word && word.error().kind == ErrorKind::Cancelled) return word.error();
    if (!word) {
        const Result<Compax3CommandResult> off =
            sendControl(compax3control::kOff, what, RetryPolicy::Idempotent);
        if (!off) return off;
        Compax3CommandResult done = *off;
        done.note =
            QCoreApplication::translate(
                "cambench::comm",
                "the drive's status could not be read (%1), so the axis was stopped by "
                "switching its power off (1100.3 = $0000), the one stop that can never power "
                "the drive; acknowledged by the drive")
                .arg(word.error().message);
        return done;
    }
    const Compax3StatusWord status{quint16(*word)};
    if (status.powerless()) {
        Compax3CommandResult result;
        result.nothingSent = true;
        result.note = QCoreApplication::translate(
            "cambench::comm", "not powered: nothing to stop (nothing was sent)");
        const Result<Compax3DriveStatus> now = this->status();
        if (now)
            result.after = *now;
        else
            result.readBackFailed = now.error().message;
        return result;
    }
    // A STOP must get through: repeating it only stops again.
    return sendControl(compax3control::kStop, what, RetryPolicy::Idempotent);
}

}  // namespace cambench::comm
