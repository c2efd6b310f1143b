#include "compax3_check.h"

#include "comm/compax3/compax3_device.h"
#include "comm/compax3/compax3_syntax.h"

#include "model/compax3/compax3_dictionary.h"
#include "model/compax3/compax3_value.h"

#include <QCoreApplication>

#include <cmath>

namespace cambench::usecases {

namespace {

using comm::Compax3Device;

const QString kNotesSource = QStringLiteral("comm/compax3/README.md");
const QString kDictionarySource = QStringLiteral("model/compax3/compax3-objects.json");
// An object no drive has: its read must be refused as "no such object".
const Compax3ObjectId kNoSuchObject{9999, 99};
constexpr int kNoSuchObjectCode = 0x0002;
constexpr int kWrongTypeCode = 0x0006;
// The serial number: a whole number every drive has (C1).
const Compax3ObjectId kSerialNumber{1, 4};
const Compax3ObjectId kActualPosition{680, 5};

// Reads (an object, the info string) pass; writes and functions never.
QString refuses(const QString&, const comm::Request& request) {
    const std::optional<comm::Compax3Request> parsed =
        comm::parseCompax3Request(comm::compax3Canonical(request.message));
    if (parsed && parsed->kind != comm::Compax3Request::Write) return {};
    return QCoreApplication::translate("cambench::usecases",
                                       "%1 was not sent: the check only reads")
        .arg(request.label);
}

CheckResult fromError(const QString& id, const QString& reading, const QString& source,
                      const Error& error) {
    if (error.kind == ErrorKind::DeviceError || error.kind == ErrorKind::InvalidData)
        return refuted(id, reading, source, error.message);
    return couldNotTell(id, reading, source, error.message);
}

CheckResult infoString(Compax3Device& drive) {
    const QString id = QStringLiteral("compax3.info_string");
    const QString reading = QCoreApplication::translate(
        "cambench::usecases",
        "the info string (_?) starts with \"Compax3\" and its second word is the drive type (C7)");
    const Result<Compax3Identity> identity = drive.identity();
    if (!identity) return fromError(id, reading, kNotesSource, identity.error());
    if (!identity->info.startsWith(QLatin1String("Compax3")) || identity->type().isEmpty())
        return refuted(id, reading, kNotesSource, identity->info);
    CheckResult result = held(id, reading, kNotesSource);
    result.observed = identity->info;
    return result;
}

// One request sent as it is, its answer parsed: for the forms the device
// interface does not send by itself ('.' separator).
Result<comm::Compax3Reply> ask(Compax3Device& drive, const QByteArray& command) {
    comm::Request request;
    request.label = QString::fromLatin1(command);
    request.message = command;
    request.longestReplyBytes = 48;
    const Result<QByteArray> answer = drive.engine().send(request);
    if (!answer) return answer.error();
    return comm::parseCompax3Reply(*answer);
}

CheckResult separators(Compax3Device& drive) {
    const QString id = QStringLiteral("compax3.separators");
    const QString reading = QCoreApplication::translate(
        "cambench::usecases",
        "O1.4 and O1,4 name the same object (the manual writes ',', the "
        "public client '.')");
    const Result<comm::Compax3Reply> comma = ask(drive, QByteArrayLiteral("O1,4"));
    if (!comma) return fromError(id, reading, kNotesSource, comma.error());
    const Result<comm::Compax3Reply> dot = ask(drive, QByteArrayLiteral("O1.4"));
    if (!dot) return fromError(id, reading, kNotesSource, dot.error());
    if (comma->kind == dot->kind && comma->text == dot->text && comma->code == dot->code)
        return held(id, reading, kNotesSource);
    const auto shown = [](const comm::Compax3Reply& reply) {
        return reply.kind == comm::Compax3Reply::Error
                   ? QStringLiteral("!%1").arg(reply.code, 4, 16, QLatin1Char('0'))
                   : reply.text;
    };
    return refuted(
        id, reading, kNotesSource,
        QCoreApplication::translate("cambench::usecases", "O1,4 answered %1, O1.4 answered %2")
            .arg(shown(*comma), shown(*dot)));
}

CheckResult hexAnswer(Compax3Device& drive) {
    const QString id = QStringLiteral("compax3.hex_answer");
    const QString reading = QCoreApplication::translate(
        "cambench::usecases", "a whole number asked for in hex ($) is answered with its $ (C8)");
    const Result<QString> value = drive.readObject(kSerialNumber, true);
    if (!value) return fromError(id, reading, kNotesSource, value.error());
    if (value->startsWith(QLatin1Char('$'))) return held(id, reading, kNotesSource);
    return refuted(id, reading, kNotesSource, *value);
}

// The drive's refusal number for a read it must refuse.
CheckResult refusal(Compax3Device& drive, const QString& id, const QString& reading,
                    const Compax3ObjectId& object, bool hex, int expected) {
    const Result<QString> value = drive.readObject(object, hex);
    if (value)
        return refuted(
            id, reading, kNotesSource,
            QCoreApplication::translate("cambench::usecases", "answered %1").arg(*value));
    if (value.error().kind != ErrorKind::DeviceError)
        return couldNotTell(id, reading, kNotesSource, value.error().message);
    if (value.error().deviceCode == expected) return held(id, reading, kNotesSource);
    return refuted(id, reading, kNotesSource, value.error().message);
}

QList<CheckResult> refusals(Compax3Device& drive) {
    return {refusal(drive, QStringLiteral("compax3.refusal.0002"),
                    QCoreApplication::translate("cambench::usecases",
                                                "an object the drive lacks is refused with "
                                                "!0002 (C5)"),
                    kNoSuchObject, false, kNoSuchObjectCode),
            refusal(drive, QStringLiteral("compax3.refusal.0006"),
                    QCoreApplication::translate("cambench::usecases",
                                                "a REAL value asked for in hex is refused with "
                                                "!0006 (C5, C8)"),
                    kActualPosition, true, kWrongTypeCode)};
}

// Whether `value` is what an object of `type` answers.
bool fitsType(const QString& value, Compax3Type type) {
    const std::optional<double> number = compax3Number(value);
    switch (type) {
        case Compax3Type::Integer:
            return number && std::floor(*number) == *number;
        case Compax3Type::Real:
            return number.has_value();
        case Compax3Type::Text:
            return !number;
    }
    return false;
}

Result<QList<CheckResult>> dictionaryObjects(Compax3Device& drive,
                                             const UseCaseProgress& progress) {
    QList<CheckResult> results;
    const QList<Compax3ObjectInfo>& objects = Compax3Dictionary::builtin().objects();
    for (qsizetype i = 0; i < objects.size(); ++i) {
        if (progress.cancelled()) return Error::cancelled();
        const Compax3ObjectInfo& object = objects.at(i);
        progress.report(i, objects.size(), object.id.text());
        if (!object.readable()) continue;  // a function: reading it says nothing
        const QString id = QStringLiteral("compax3.object.") + object.id.text();
        const QString reading =
            QCoreApplication::translate("cambench::usecases", "object %1 (%2) exists and is %3")
                .arg(object.id.text(), object.name, compax3TypeKey(object.type));
        const Result<QString> value = drive.readObject(object.id);
        if (!value) {
            if (value.error().kind == ErrorKind::Cancelled) return value.error();
            results << fromError(id, reading, kDictionarySource, value.error());
        } else if (fitsType(*value, object.type)) {
            results << held(id, reading, kDictionarySource);
        } else {
            results << refuted(
                id, reading, kDictionarySource,
                QCoreApplication::translate("cambench::usecases", "answered %1").arg(*value));
        }
    }
    return results;
}

Result<QList<CheckResult>> run(comm::DeviceConnection& connection,
                               const UseCaseProgress& progress) {
    auto* drive = dynamic_cast<Compax3Device*>(&connection);
    if (!drive) return Error::usage(QStringLiteral("not a Compax3 connection"));
    QList<CheckResult> results{infoString(*drive), separators(*drive), hexAnswer(*drive)};
    results << refusals(*drive);
    const Result<QList<CheckResult>> objects = dictionaryObjects(*drive, progress);
    if (!objects) return objects.error();
    results << *objects;
    return results;
}

}  // namespace

void registerCompax3Check(CheckRegistry& registry) {
    registry.add({QStringLiteral("compax3"), refuses, run});
}

}  // namespace cambench::usecases
