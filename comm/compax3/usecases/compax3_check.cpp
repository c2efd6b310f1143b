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
// An object no drive has: its read must be refused as "no such object".
const Compax3ObjectId kNoSuchObject{9999, 99};
constexpr int kNoSuchObjectCode = 0x0002;
constexpr int kWrongTypeCode = 0x0006;
// The serial number, a text every drive has, and the status word, a whole
// number (C1).
const Compax3ObjectId kSerialNumber{1, 4};
const Compax3ObjectId kStatusWord{1000, 3};
// The info string's fixed length plus some room; the longest value answer.
constexpr int kLongestAnswer = 48;

// Reads (an object, the info string) pass; writes and functions never.
QString refuses(const QString&, const comm::Request& request) {
    const std::optional<comm::Compax3Request> parsed =
        comm::parseCompax3Request(comm::compax3Canonical(request.message));
    const bool reads = parsed && parsed->kind != comm::Compax3Request::Write;
    return reads ? QString() : notReadingRequest(request);
}

CheckResult infoString(Compax3Device& drive) {
    const Reading reading{QStringLiteral("compax3.info_string"),
                          QCoreApplication::translate("cambench::usecases",
                                                      "the info string (_?) starts with "
                                                      "\"Compax3\" and its second word is the "
                                                      "drive type (C7)"),
                          kNotesSource};
    const Result<Compax3Identity> identity = drive.identity();
    if (!identity) return reading.failed(identity.error());
    if (!identity->info.startsWith(QLatin1String("Compax3")) || identity->type().isEmpty())
        return reading.refuted(identity->info);
    return reading.held(identity->info);
}

// One request sent as it is, its answer parsed: for the forms the device
// interface does not send by itself ('.' separator).
Result<comm::Compax3Reply> ask(Compax3Device& drive, const QByteArray& command) {
    comm::Request request;
    request.label = QString::fromLatin1(command);
    request.message = command;
    request.longestReplyBytes = kLongestAnswer;
    const Result<QByteArray> answer = drive.engine().send(request);
    if (!answer) return answer.error();
    return comm::parseCompax3Reply(*answer);
}

QString replyText(const comm::Compax3Reply& reply) {
    return reply.kind == comm::Compax3Reply::Error
               ? QStringLiteral("!%1").arg(reply.code, 4, 16, QLatin1Char('0'))
               : reply.text;
}

CheckResult separators(Compax3Device& drive) {
    const Reading reading{QStringLiteral("compax3.separators"),
                          QCoreApplication::translate("cambench::usecases",
                                                      "O1.4 and O1,4 name the same object (the "
                                                      "manual writes ',', the public client '.')"),
                          kNotesSource};
    const Result<comm::Compax3Reply> comma = ask(drive, QByteArrayLiteral("O1,4"));
    if (!comma) return reading.failed(comma.error());
    const Result<comm::Compax3Reply> dot = ask(drive, QByteArrayLiteral("O1.4"));
    if (!dot) return reading.failed(dot.error());
    if (replyText(*comma) == replyText(*dot)) return reading.held();
    return reading.refuted(
        QCoreApplication::translate("cambench::usecases", "O1,4 answered %1, O1.4 answered %2")
            .arg(replyText(*comma), replyText(*dot)));
}

CheckResult hexAnswer(Compax3Device& drive) {
    const Reading reading{
        QStringLiteral("compax3.hex_answer"),
        QCoreApplication::translate("cambench::usecases",
                                    "a whole number asked for in hex ($) is answered with its $ "
                                    "(C8)"),
        kNotesSource};
    const Result<QString> value = drive.readObject(kStatusWord, true);
    if (!value) return reading.failed(value.error());
    return value->startsWith(QLatin1Char('$')) ? reading.held() : reading.refuted(*value);
}

// Where the dictionary in use comes from: the shipped file (provisional
// meanings) or the one the person loaded.
QString dictionarySource(const Compax3Dictionary& dictionary) {
    return dictionary.source() == Compax3Dictionary::builtin().source()
               ? QStringLiteral(
                     "provisional: shipped dictionary, "
                     "model/compax3/compax3-objects.json")
               : dictionary.source();
}

// The drive's refusal number for a read it must refuse; held shows the
// meaning the dictionary in use gives it.
CheckResult refusal(Compax3Device& drive, const Reading& reading, const Compax3ObjectId& object,
                    bool hex, int expected) {
    const Result<QString> value = drive.readObject(object, hex);
    if (value)
        return reading.refuted(
            QCoreApplication::translate("cambench::usecases", "answered %1").arg(*value));
    if (value.error().kind != ErrorKind::DeviceError) return reading.failed(value.error());
    if (value.error().deviceCode == expected) return reading.held(value.error().message);
    return reading.refuted(value.error().message);
}

// The refusal a missing object gets: the one the dictionary's table says
// means "not on this drive", else the manual's !0002.
int noSuchObjectCode(const Compax3RefusalTable& table) {
    for (const Compax3RefusalMeaning& entry : table)
        if (entry.absent) return entry.code;
    return kNoSuchObjectCode;
}

QString codeText(int code) {
    return QStringLiteral("%1").arg(code, 4, 16, QLatin1Char('0')).toUpper();
}

QList<CheckResult> refusals(Compax3Device& drive) {
    const QString source = dictionarySource(drive.dictionary());
    const int absentCode = noSuchObjectCode(drive.dictionary().refusals());
    const Reading noSuchObject{
        QStringLiteral("compax3.refusal.") + codeText(absentCode),
        QCoreApplication::translate("cambench::usecases",
                                    "an object the drive lacks is refused with !%1 (C5)")
            .arg(codeText(absentCode)),
        source};
    const Reading wrongType{QStringLiteral("compax3.refusal.0006"),
                            QCoreApplication::translate("cambench::usecases",
                                                        "a text asked for in hex is refused with "
                                                        "!0006 (C5, C8)"),
                            source};
    return {refusal(drive, noSuchObject, kNoSuchObject, false, absentCode),
            refusal(drive, wrongType, kSerialNumber, true, kWrongTypeCode)};
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
    const QString source = dictionarySource(drive.dictionary());
    const QList<Compax3ObjectInfo>& objects = drive.dictionary().objects();
    for (qsizetype i = 0; i < objects.size(); ++i) {
        if (progress.cancelled()) return Error::cancelled();
        const Compax3ObjectInfo& object = objects.at(i);
        progress.report(i, objects.size(), object.id.text());
        if (!object.readable()) continue;  // a function: reading it says nothing
        const Reading reading{
            QStringLiteral("compax3.object.") + object.id.text(),
            QCoreApplication::translate("cambench::usecases", "object %1 (%2) exists and is %3")
                .arg(object.id.text(), object.name, compax3TypeKey(object.type)),
            source};
        const Result<QString> value = drive.readObject(object.id);
        if (!value && value.error().kind == ErrorKind::Cancelled) return value.error();
        if (!value) {
            results << reading.failed(value.error());
        } else if (fitsType(*value, object.type)) {
            results << reading.held();
        } else {
            results << reading.refuted(
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

// --dictionary FILE: the person's own object dictionary (and refusals).
Result<CheckTable> dictionaryFile(const QString& path) {
    const Result<Compax3Dictionary> dictionary = Compax3Dictionary::load(path);
    if (!dictionary) return dictionary.error();
    return CheckTable{{}, {}, [dictionary = *dictionary](comm::DeviceConnection& connection) {
                          if (auto* drive = dynamic_cast<Compax3Device*>(&connection))
                              drive->setDictionary(dictionary);
                      }};
}

}  // namespace

FamilyCheck compax3Check() {
    FamilyCheck check;
    check.refuses = refuses;
    check.run = run;
    check.tables = {CheckTableOption{QStringLiteral("--dictionary"), dictionaryFile}};
    return check;
}

}  // namespace cambench::usecases
