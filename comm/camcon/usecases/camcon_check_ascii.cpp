// The ASCII protocols' part of the CamCon check: the catalogue's queries,
// the Multiuser block numbering, the Cam-BUS token (listening only).
#include "camcon_check_parts.h"

#include "comm/camcon/ascii/ascii_camcon.h"
#include "comm/camcon/ascii/catalogue.h"
#include "comm/camcon/cambus/cambus_backend.h"

#include <QCoreApplication>

namespace cambench::usecases::camcon_check {

namespace {

QString commandName(const comm::CommandSpec& spec) {
    return QLatin1Char(spec.kind) + QString::fromLatin1(spec.name);
}

// The request's numbers as 0 (the first program, output, channel, block);
// nullopt when it needs a text, which the check does not make up.
std::optional<comm::Fields> zeroFields(const comm::CommandSpec& spec) {
    comm::Fields fields;
    for (const comm::FieldSpec& field : spec.request) {
        if (field.type != comm::FieldType::Hex && field.type != comm::FieldType::SignedHex)
            return std::nullopt;
        fields.set(field.name, 0);
    }
    return fields;
}

// What asking `spec` with 0 for its numbers showed; only a cancel fails.
Result<CheckResult> askedWithZeros(comm::AsciiLink& link, const comm::CommandSpec& spec,
                                   const Reading& reading, SilentLine& line) {
    const std::optional<comm::Fields> fields = zeroFields(spec);
    if (!fields)
        return reading.couldNotTell(
            QCoreApplication::translate("cambench::usecases", "it asks with a text"));
    if (const std::optional<CheckResult> skipped = line.skip(reading)) return *skipped;
    const Result<comm::Fields> reply = link.call(spec, *fields);
    line.answered(reply || reply.error().kind != ErrorKind::Communication);
    if (reply) return reading.held();
    const Error& error = reply.error();
    if (error.kind == ErrorKind::Cancelled) return error;
    if (error.kind == ErrorKind::NotUnderstood) {
        return reading.refuted(QCoreApplication::translate("cambench::usecases",
                                                           "the device does not know it (:Z): %1")
                                   .arg(error.message));
    }
    if (error.kind == ErrorKind::DeviceError) {
        // It knows the command; ERR to the numbers 0 says nothing of the format.
        return reading.couldNotTell(
            QCoreApplication::translate("cambench::usecases",
                                        "it answered ERR %1 when asked with 0")
                .arg(error.deviceCode));
    }
    return reading.failed(error);
}

// The catalogue line to correct; a guessed format names its reading first
// ("provisional: P-ASCII-2, …"), so that the report says which one.
QString catalogueSource(const comm::CommandSpec& spec, const QString& name) {
    const QString line = QStringLiteral("comm/camcon/ascii/catalogue.cpp: ") + name;
    if (!spec.provisional) return line;
    return QLatin1String(spec.provisional) + QStringLiteral("; ") + line;
}

}  // namespace

std::optional<CheckResult> SilentLine::skip(const Reading& reading) const {
    if (m_silent < kGiveUpAfter) return std::nullopt;
    return reading.couldNotTell(
        QCoreApplication::translate("cambench::usecases", "the device stopped answering"));
}

Result<QList<CheckResult>> catalogueQueries(comm::AsciiCamCon& device,
                                            const UseCaseProgress& progress) {
    QList<const comm::CommandSpec*> queries;
    for (const comm::CommandSpec& spec : comm::commandCatalogue()) {
        if (spec.kind == comm::kQuery) queries << &spec;
    }
    QList<CheckResult> results;
    SilentLine line;
    for (const comm::CommandSpec* spec : queries) {
        if (progress.cancelled()) return Error::cancelled();
        const QString name = commandName(*spec);
        progress.report(results.size(), queries.size(), name);
        const Reading reading{
            QStringLiteral("ascii.") + name,
            QCoreApplication::translate("cambench::usecases", "%1 is answered as manual %2 reads%3")
                .arg(name, QLatin1String(spec->section),
                     spec->provisional ? QCoreApplication::translate("cambench::usecases",
                                                                     " (provisional format)")
                                       : QString()),
            catalogueSource(*spec, name)};
        const Result<CheckResult> result = askedWithZeros(device.link(), *spec, reading, line);
        if (!result) return result.error();
        results << *result;
    }
    return results;
}

Result<QList<CheckResult>> multiuserNumbering(comm::AsciiCamCon& device) {
    // Two block numbers the run's own requests are unlikely to hold; a
    // repeat of the first must be answered again (with the old reply).
    constexpr int kBlock = 17;
    constexpr int kTurnaroundMs = 100;
    const Reading reading{
        QStringLiteral("multiuser.block_numbers"),
        QCoreApplication::translate("cambench::usecases",
                                    "a request under a new block number is answered, and so is a "
                                    "repeat of that number (with the last reply, not executed "
                                    "again)"),
        QStringLiteral("comm/camcon/ascii/ascii_backend.h (block numbers)")};
    comm::AsciiLink& link = device.link();
    const int number = link.settings().device;
    QStringList silentAt;
    for (const int block : {kBlock, kBlock, kBlock + 1}) {
        const Result<bool> answered = link.ping(number, block, kTurnaroundMs);
        if (!answered) return answered.error();
        if (!*answered) silentAt << QString::number(block);
    }
    if (silentAt.isEmpty()) return QList<CheckResult>{reading.held()};
    return QList<CheckResult>{reading.couldNotTell(
        QCoreApplication::translate("cambench::usecases",
                                    "no answer under block numbers %1 (of %2, %2, %3)")
            .arg(silentAt.join(QLatin1String(", ")))
            .arg(kBlock)
            .arg(kBlock + 1))};
}

Result<QList<CheckResult>> camBusTiming(comm::AsciiCamCon& device) {
    constexpr int kListenMs = 1000;
    const Reading reading{
        QStringLiteral("cambus.token_round"),
        QCoreApplication::translate("cambench::usecases",
                                    "every user in the bus's table gets the token within a second "
                                    "(P11: each answers within T = 10 ms)"),
        QStringLiteral("comm/camcon/cambus/README.md (Timing, P11)")};
    auto* backend = dynamic_cast<comm::CamBusBackend*>(&device.engine().backend());
    if (!backend)
        return QList<CheckResult>{reading.couldNotTell(
            QCoreApplication::translate("cambench::usecases", "not a Cam-BUS line"))};
    const comm::CamBusView before = backend->view();
    const Status listened = device.engine().listen(kListenMs);
    if (!listened) return listened.error();
    const comm::CamBusView after = backend->view();
    const qint64 tokens = after.tokens - before.tokens;
    if (tokens <= 0) {
        return QList<CheckResult>{reading.couldNotTell(
            QCoreApplication::translate("cambench::usecases", "no token heard in %1 ms")
                .arg(kListenMs))};
    }
    QStringList missed;
    for (auto it = after.users.cbegin(); it != after.users.cend(); ++it) {
        if (it->answers && it->lastTokenMs < before.nowMs) missed << QString::number(it.key());
    }
    const QString heard = QCoreApplication::translate("cambench::usecases", "%1 tokens in %2 ms")
                              .arg(tokens)
                              .arg(kListenMs);
    if (missed.isEmpty()) return QList<CheckResult>{reading.held(heard)};
    return QList<CheckResult>{reading.refuted(
        QCoreApplication::translate("cambench::usecases", "%1; users %2 did not get the token")
            .arg(heard, missed.join(QLatin1String(", "))))};
}

}  // namespace cambench::usecases::camcon_check
