#include "item_outcome.h"

#include <QStringList>

namespace cambench::usecases {

QString writeStateText(WriteState state) {
    switch (state) {
        case WriteState::Written:
            return QCoreApplication::translate("cambench::usecases", "written");
        case WriteState::Unchanged:
            return QCoreApplication::translate("cambench::usecases", "unchanged");
        case WriteState::Failed:
            return QCoreApplication::translate("cambench::usecases", "failed");
        case WriteState::ChangedThoughFailed:
            return QCoreApplication::translate("cambench::usecases",
                                               "changed though the write failed");
        case WriteState::Unknown:
            return QCoreApplication::translate("cambench::usecases", "failed, state unknown");
        case WriteState::NotSent:
            return QCoreApplication::translate("cambench::usecases", "not sent");
    }
    return {};
}

QString outcomeText(const QString& label, WriteState state, const QString& actualText,
                    const Error& error, const QString& note) {
    QString text = QStringLiteral("%1: %2").arg(label, writeStateText(state));
    switch (state) {
        case WriteState::Written:
        case WriteState::Unchanged:
            if (!note.isEmpty()) text += QStringLiteral(" (%1)").arg(note);
            return text;
        case WriteState::Failed:
            text += QCoreApplication::translate("cambench::usecases", ", the device keeps %1")
                        .arg(actualText);
            break;
        case WriteState::ChangedThoughFailed:
            text += QCoreApplication::translate("cambench::usecases", ", the device NOW HOLDS %1")
                        .arg(actualText);
            break;
        case WriteState::Unknown:
            text += QCoreApplication::translate("cambench::usecases",
                                                ", what the device holds now could not be read");
            break;
        case WriteState::NotSent:
            break;
    }
    if (!error.message.isEmpty()) text += QStringLiteral(": ") + error.message;
    if (!note.isEmpty()) text += QStringLiteral(" (%1)").arg(note);
    return text;
}

int OutcomeTally::count(WriteState state) const {
    int n = 0;
    for (const OutcomeLine& line : m_lines) n += line.state == state ? 1 : 0;
    return n;
}

bool OutcomeTally::complete() const {
    for (const OutcomeLine& line : m_lines) {
        if (line.state != WriteState::Written && line.state != WriteState::Unchanged) return false;
    }
    return true;
}

Error OutcomeTally::firstError() const {
    for (const OutcomeLine& line : m_lines) {
        if (line.state == WriteState::Written || line.state == WriteState::Unchanged) continue;
        if (line.error.kind != ErrorKind::None) return line.error;
        return Error::communication(line.label);
    }
    return {};
}

QString OutcomeTally::summary() const {
    QStringList parts{QCoreApplication::translate("cambench::usecases", "%1 written")
                          .arg(count(WriteState::Written)),
                      QCoreApplication::translate("cambench::usecases", "%1 unchanged")
                          .arg(count(WriteState::Unchanged))};
    const struct {
        WriteState state;
        const char* text;
    } others[] = {
        {WriteState::Failed,
         QT_TRANSLATE_NOOP("cambench::usecases", "%1 failed (the device keeps its old values)")},
        {WriteState::ChangedThoughFailed,
         QT_TRANSLATE_NOOP("cambench::usecases", "%1 CHANGED THOUGH THE WRITE FAILED")},
        {WriteState::Unknown,
         QT_TRANSLATE_NOOP("cambench::usecases", "%1 failed with the device's state unknown")},
        {WriteState::NotSent, QT_TRANSLATE_NOOP("cambench::usecases", "%1 not sent")},
    };
    for (const auto& other : others) {
        if (const int n = count(other.state))
            parts << QCoreApplication::translate("cambench::usecases", other.text).arg(n);
    }
    // Whole phrases: the CLI prints English without a catalogue, so no "%n".
    const QString joined = parts.join(QLatin1String(", "));
    if (total() == 1)
        return QCoreApplication::translate("cambench::usecases", "1 item: %1").arg(joined);
    return QCoreApplication::translate("cambench::usecases", "%1 items: %2")
        .arg(total())
        .arg(joined);
}

OutcomeLine failedWriteLine(const QString& label, const Error& error, bool readOk, bool isOld,
                            bool isWanted, const QString& actual) {
    WriteState state = WriteState::Unknown;
    if (readOk)
        state = isWanted ? WriteState::Written
                : isOld  ? WriteState::Failed
                         : WriteState::ChangedThoughFailed;
    const QString note =
        state == WriteState::Written
            ? QCoreApplication::translate("cambench::usecases", "written, as read back after: %1")
                  .arg(error.message)
            : QString();
    const Error shown = state == WriteState::Written ? Error{} : error;
    return {label, state, outcomeText(label, state, actual, shown, note), shown};
}

}  // namespace cambench::usecases
