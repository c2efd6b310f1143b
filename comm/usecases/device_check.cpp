#include "device_check.h"

#include <QCoreApplication>
#include <QJsonArray>

namespace cambench::usecases {

namespace {

// The engine's gate for the length of one check; taken off again however
// the check ends.
class GateScope {
public:
    GateScope(comm::RequestEngine& engine, comm::RequestEngine::RequestGate gate)
        : m_engine(engine) {
        m_engine.setRequestGate(std::move(gate));
    }
    ~GateScope() { m_engine.setRequestGate({}); }
    GateScope(const GateScope&) = delete;
    GateScope& operator=(const GateScope&) = delete;

private:
    comm::RequestEngine& m_engine;
};

}  // namespace

QString checkVerdictText(CheckVerdict verdict) {
    switch (verdict) {
        case CheckVerdict::Held:
            return QStringLiteral("held");
        case CheckVerdict::Refuted:
            return QStringLiteral("refuted");
        case CheckVerdict::CouldNotTell:
            break;
    }
    return QStringLiteral("could not tell");
}

CheckResult Reading::held(QString observed) const {
    return {id, text, source, CheckVerdict::Held, std::move(observed)};
}

CheckResult Reading::refuted(QString observed) const {
    return {id, text, source, CheckVerdict::Refuted, std::move(observed)};
}

CheckResult Reading::couldNotTell(QString why) const {
    return {id, text, source, CheckVerdict::CouldNotTell, std::move(why)};
}

CheckResult Reading::failed(const Error& error) const {
    switch (error.kind) {
        case ErrorKind::DeviceError:
        case ErrorKind::NotUnderstood:
        case ErrorKind::InvalidData:
            return refuted(error.message);
        default:
            return couldNotTell(error.message);
    }
}

QString notReadingRequest(const comm::Request& request) {
    return QCoreApplication::translate("cambench::usecases",
                                       "%1 was not sent: the check only reads")
        .arg(request.label);
}

int CheckReport::count(CheckVerdict verdict) const {
    int n = 0;
    for (const CheckResult& result : results) n += result.verdict == verdict ? 1 : 0;
    return n;
}

QString checkReportText(const CheckReport& report) {
    QString text = QStringLiteral("check of %1 over %2: %3\n")
                       .arg(report.familyId, report.protocolId, report.device);
    for (const CheckResult& result : report.results) {
        text += QStringLiteral("%1  %2: %3")
                    .arg(checkVerdictText(result.verdict), result.id, result.reading);
        if (!result.observed.isEmpty()) text += QStringLiteral(" - ") + result.observed;
        text += QStringLiteral(" [%1]\n").arg(result.source);
    }
    text += QStringLiteral(
                "%1 held, %2 refuted, %3 could not tell; %4 requests sent, all "
                "reading")
                .arg(report.count(CheckVerdict::Held))
                .arg(report.count(CheckVerdict::Refuted))
                .arg(report.count(CheckVerdict::CouldNotTell))
                .arg(report.requestsSent);
    if (report.refusedRequests > 0)
        text += QStringLiteral("; %1 other requests were kept off the line")
                    .arg(report.refusedRequests);
    return text + QLatin1Char('\n');
}

QJsonObject checkReportJson(const CheckReport& report) {
    QJsonArray results;
    for (const CheckResult& result : report.results) {
        QJsonObject entry{{QStringLiteral("id"), result.id},
                          {QStringLiteral("verdict"), checkVerdictText(result.verdict)},
                          {QStringLiteral("reading"), result.reading},
                          {QStringLiteral("source"), result.source}};
        if (!result.observed.isEmpty()) entry.insert(QStringLiteral("observed"), result.observed);
        results << entry;
    }
    return {{QStringLiteral("family"), report.familyId},
            {QStringLiteral("protocol"), report.protocolId},
            {QStringLiteral("device"), report.device},
            {QStringLiteral("held"), report.count(CheckVerdict::Held)},
            {QStringLiteral("refuted"), report.count(CheckVerdict::Refuted)},
            {QStringLiteral("couldNotTell"), report.count(CheckVerdict::CouldNotTell)},
            {QStringLiteral("requestsSent"), report.requestsSent},
            {QStringLiteral("refusedRequests"), report.refusedRequests},
            {QStringLiteral("results"), results}};
}

CheckRegistry& CheckRegistry::instance() {
    static CheckRegistry registry;
    return registry;
}

void CheckRegistry::add(FamilyCheck check) {
    m_checks.append(std::move(check));
}

const FamilyCheck* CheckRegistry::find(const QString& familyId) const {
    for (const FamilyCheck& check : m_checks) {
        if (check.familyId == familyId) return &check;
    }
    return nullptr;
}

QStringList CheckRegistry::tableOptions() const {
    QStringList options;
    for (const FamilyCheck& check : m_checks)
        for (const CheckTableOption& table : check.tables) options << table.option;
    return options;
}

Result<CheckTable> CheckRegistry::loadTable(const QString& option, const QString& path) const {
    for (const FamilyCheck& check : m_checks) {
        for (const CheckTableOption& table : check.tables) {
            if (table.option != option) continue;
            const Result<CheckTable> loaded = table.load(path);
            if (!loaded)
                return Error::invalidData(
                    QCoreApplication::translate("cambench::usecases", "%1 %2 was not loaded: %3")
                        .arg(option, path, loaded.error().message));
            return CheckTable{check.familyId, option, loaded->use};
        }
    }
    return Error::usage(
        QCoreApplication::translate("cambench::usecases", "no family's check takes %1")
            .arg(option));
}

Result<CheckReport> checkDevice(comm::DeviceConnection& connection, const UseCaseProgress& progress,
                                const QList<CheckTable>& tables) {
    const FamilyCheck* check = CheckRegistry::instance().find(connection.familyId());
    if (!check) {
        return Error::usage(QCoreApplication::translate("cambench::usecases",
                                                        "There is no check for %1 devices yet.")
                                .arg(connection.familyId()));
    }
    for (const CheckTable& table : tables) {
        if (table.familyId != connection.familyId())
            return Error::usage(QCoreApplication::translate(
                                    "cambench::usecases",
                                    "%1 is a table of %2 devices; the device connected is a %3 "
                                    "device: leave the option out")
                                    .arg(table.option, table.familyId, connection.familyId()));
    }
    for (const CheckTable& table : tables) table.use(connection);
    CheckReport report;
    report.familyId = connection.familyId();
    report.protocolId = connection.protocolId();
    comm::RequestEngine& engine = connection.engine();
    const int requestsBefore = engine.stats().requests;
    const int refusedBefore = engine.stats().refusedByGate;
    Result<QList<CheckResult>> results = Error::cancelled();
    {
        const QString protocol = report.protocolId;
        const GateScope gate(engine, [check, protocol](const comm::Request& request) {
            return check->refuses(protocol, request);
        });
        const Result<QString> identity = connection.identify();
        report.device = identity ? *identity : identity.error().message;
        results = check->run(connection, progress);
    }
    report.requestsSent = engine.stats().requests - requestsBefore;
    report.refusedRequests = engine.stats().refusedByGate - refusedBefore;
    if (!results) return results.error();
    report.results = *results;
    return report;
}

}  // namespace cambench::usecases
