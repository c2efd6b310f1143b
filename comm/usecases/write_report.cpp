#include "write_report.h"

#include <QCoreApplication>

namespace cambench::usecases {

namespace {

// Calls `visit(outcome)` for every item of the report, in plan order.
template <class Visit>
void forEach(const WriteReport& report, Visit visit) {
    for (const auto& outcome : report.settings) visit(outcome);
    for (const auto& outcome : report.programNames) visit(outcome);
    for (const auto& outcome : report.tracks) visit(outcome);
    for (const auto& outcome : report.deadTimes) visit(outcome);
    for (const auto& outcome : report.outputNames) visit(outcome);
    for (const auto& outcome : report.users) visit(outcome);
    for (const auto& outcome : report.plcNetworks) visit(outcome);
}

template <class T>
QString lineText(const ItemOutcome<T>& outcome) {
    QString text = QStringLiteral("%1: %2").arg(outcome.label, writeStateText(outcome.state));
    switch (outcome.state) {
        case WriteState::Written:
        case WriteState::Unchanged:
            if (!outcome.note.isEmpty()) text += QStringLiteral(" (%1)").arg(outcome.note);
            return text;
        case WriteState::Failed:
            text += QCoreApplication::translate("cambench::usecases", ", the device keeps %1")
                        .arg(outcome.actualText);
            break;
        case WriteState::ChangedThoughFailed:
            text += QCoreApplication::translate("cambench::usecases", ", the device NOW HOLDS %1")
                        .arg(outcome.actualText);
            break;
        case WriteState::Unknown:
            text += QCoreApplication::translate("cambench::usecases",
                                                ", what the device holds now could not be read");
            break;
        case WriteState::NotSent:
            break;
    }
    if (!outcome.error.message.isEmpty()) text += QStringLiteral(": ") + outcome.error.message;
    if (!outcome.note.isEmpty()) text += QStringLiteral(" (%1)").arg(outcome.note);
    return text;
}

}  // namespace

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

int WriteReport::count(WriteState state) const {
    int n = 0;
    forEach(*this, [&](const auto& outcome) { n += outcome.state == state ? 1 : 0; });
    return n;
}

int WriteReport::total() const {
    int n = 0;
    forEach(*this, [&](const auto&) { ++n; });
    return n;
}

bool WriteReport::complete() const {
    bool complete = true;
    forEach(*this, [&](const auto& outcome) { complete = complete && outcome.ok(); });
    return complete;
}

Error WriteReport::firstError() const {
    Error first;
    forEach(*this, [&](const auto& outcome) {
        if (first.kind == ErrorKind::None && !outcome.ok()) {
            first = outcome.error;
            if (first.kind == ErrorKind::None) first = Error::communication(outcome.label);
        }
    });
    return first;
}

QList<OutcomeLine> WriteReport::lines() const {
    QList<OutcomeLine> lines;
    forEach(*this, [&](const auto& outcome) {
        lines.append({outcome.label, outcome.state, lineText(outcome)});
    });
    return lines;
}

QString WriteReport::summary() const {
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

}  // namespace cambench::usecases
