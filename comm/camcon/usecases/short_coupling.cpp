#include "short_coupling.h"

#include "value_text.h"

#include "comm/camcon/table/short_client.h"

#include <functional>

namespace cambench::usecases {

namespace {

using comm::table::ShortClient;

// The one shape of every checked short write: read, skip when equal,
// write, read back, and say what the device holds.
template <class T>
OutcomeLine checkedWrite(const QString& label, const T& wanted,
                         const std::function<Result<T>()>& read,
                         const std::function<Status()>& write,
                         const std::function<QString(const T&)>& text) {
    ItemOutcome<T> outcome;
    outcome.label = label;
    const Result<T> before = read();
    if (!before) {
        outcome.state = WriteState::NotSent;
        outcome.error = before.error();
        return outcomeLine(outcome);
    }
    if (*before == wanted) {
        outcome.state = WriteState::Unchanged;
        outcome.actual = wanted;
        outcome.actualText = text(wanted);
        return outcomeLine(outcome);
    }
    const Status written = write();
    const Result<T> after = read();
    if (after) {
        outcome.actual = *after;
        outcome.actualText = text(*after);
    }
    if (written && after && *after == wanted) {
        outcome.state = WriteState::Written;
        outcome.note = QCoreApplication::translate("cambench::usecases", "the device reports %1")
                           .arg(outcome.actualText);
    } else if (written && !after) {
        // The device acknowledged; only the check is missing.
        outcome.state = WriteState::Written;
        outcome.note = QCoreApplication::translate("cambench::usecases",
                                                   "acknowledged; reading it back failed: %1")
                           .arg(after.error().message);
    } else if (!after) {
        outcome.state = WriteState::Unknown;
        outcome.error = written.error();
    } else {
        outcome.state = *after == *before ? WriteState::Failed : WriteState::ChangedThoughFailed;
        outcome.error = written ? Error::device(0, QCoreApplication::translate(
                                                       "cambench::usecases",
                                                       "the device acknowledged the write, but "
                                                       "reads back another value"))
                                : written.error();
    }
    return outcomeLine(outcome);
}

}  // namespace

OutcomeLine shortResetErrors(ShortClient& client) {
    ItemOutcome<int> outcome;
    outcome.label = QCoreApplication::translate("cambench::usecases", "error reset (0x02)");
    const Status reset = client.resetErrors();
    const Result<comm::table::ShortStatus> after = client.status();
    if (after) {
        outcome.actual = after->deviceStatus;
        outcome.actualText = comm::table::shortDeviceStatusText(after->deviceStatus);
    }
    if (reset) {
        outcome.state = WriteState::Written;
        outcome.note =
            after ? QCoreApplication::translate("cambench::usecases", "device status now: %1")
                        .arg(outcome.actualText)
                  : QCoreApplication::translate("cambench::usecases",
                                                "reading the device status failed: %1")
                        .arg(after.error().message);
        if (after && after->deviceStatus != 0)
            outcome.note += QCoreApplication::translate(
                "cambench::usecases",
                "; the cause is still there: check the encoder and the outputs");
    } else {
        outcome.state = after ? WriteState::Failed : WriteState::Unknown;
        outcome.error = reset.error();
    }
    return outcomeLine(outcome);
}

OutcomeLine shortChangeProgram(ShortClient& client, int program) {
    return checkedWrite<int>(
        QCoreApplication::translate("cambench::usecases", "active program (0x03)"), program,
        [&client]() -> Result<int> {
            const Result<comm::table::ShortStatus> status = client.status();
            if (!status) return status.error();
            return status->program;
        },
        [&client, program] { return client.changeProgram(program); },
        [](const int& p) {
            return QCoreApplication::translate("cambench::usecases", "program %1").arg(p);
        });
}

OutcomeLine shortWriteTrack(ShortClient& client, int program, const Track& track) {
    return checkedWrite<QList<Cam>>(
        QCoreApplication::translate("cambench::usecases", "program %1, output %2 (0x05)")
            .arg(program)
            .arg(track.output),
        track.cams,
        [&client, program, output = track.output]() -> Result<QList<Cam>> {
            const Result<Track> read = client.readTrack(program, output);
            if (!read) return read.error();
            return read->cams;
        },
        [&client, program, &track] { return client.writeTrack(program, track); },
        [output = track.output](const QList<Cam>& cams) {
            Track shown;
            shown.output = output;
            shown.cams = cams;
            return camsText(shown);
        });
}

OutcomeLine shortWriteDeadTime(ShortClient& client, int output, int tenthsMs) {
    return checkedWrite<int>(
        QCoreApplication::translate("cambench::usecases", "dead time of output %1 (0x07)")
            .arg(output),
        tenthsMs, [&client, output] { return client.readDeadTime(output); },
        [&client, output, tenthsMs] { return client.writeDeadTime(output, tenthsMs); },
        [](const int& tenths) { return deadTimeText(tenths); });
}

}  // namespace cambench::usecases
