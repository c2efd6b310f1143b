#include "write_report.h"

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
            text += QStringLiteral(", the device keeps %1").arg(outcome.actualText);
            break;
        case WriteState::ChangedThoughFailed:
            text += QStringLiteral(", the device NOW HOLDS %1").arg(outcome.actualText);
            break;
        case WriteState::Unknown:
            text += QStringLiteral(", what the device holds now could not be read");
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
            return QStringLiteral("written");
        case WriteState::Unchanged:
            return QStringLiteral("unchanged");
        case WriteState::Failed:
            return QStringLiteral("failed");
        case WriteState::ChangedThoughFailed:
            return QStringLiteral("changed though the write failed");
        case WriteState::Unknown:
            return QStringLiteral("failed, state unknown");
        case WriteState::NotSent:
            return QStringLiteral("not sent");
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
    QStringList parts{QStringLiteral("%1 written").arg(count(WriteState::Written)),
                      QStringLiteral("%1 unchanged").arg(count(WriteState::Unchanged))};
    const struct {
        WriteState state;
        const char* text;
    } others[] = {
        {WriteState::Failed, "%1 failed (the device keeps its old values)"},
        {WriteState::ChangedThoughFailed, "%1 CHANGED THOUGH THE WRITE FAILED"},
        {WriteState::Unknown, "%1 failed with the device's state unknown"},
        {WriteState::NotSent, "%1 not sent"},
    };
    for (const auto& other : others) {
        if (const int n = count(other.state)) parts << QString::fromLatin1(other.text).arg(n);
    }
    return QStringLiteral("%1 items: %2").arg(total()).arg(parts.join(QLatin1String(", ")));
}

}  // namespace cambench::usecases
