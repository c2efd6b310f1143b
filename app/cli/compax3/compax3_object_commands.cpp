// c3 info, read, write, scan, watch, status.
#include "compax3_commands.h"

#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"

#include "comm/compax3/compax3_syntax.h"
#include "comm/compax3/usecases/compax3_read_objects.h"
#include "model/compax3/compax3_family_id.h"

#include <QDateTime>
#include <QJsonArray>
#include <QJsonObject>
#include <QThread>

namespace cambench::cli {

namespace {

using comm::Compax3Device;
using comm::Compax3DriveStatus;
using comm::JobContext;
using usecases::Compax3Reading;
using Reading = Compax3Reading;

// The remaining words of the command, options taken first.
QStringList takeRest(CommandArgs& args) {
    QStringList words;
    for (QString word = args.takePositional(); !word.isEmpty(); word = args.takePositional())
        words << word;
    return words;
}

QJsonObject statusJson(const Compax3DriveStatus& status) {
    QJsonObject bits;
    for (const comm::Compax3StatusBit& bit : comm::compax3StatusBits(status.status.word))
        bits.insert(bit.name, bit.on);
    return {{QStringLiteral("statusWord"), int(status.status.word)},
            {QStringLiteral("bits"), bits},
            {QStringLiteral("lastError"), status.lastError},
            {QStringLiteral("lastErrorText"), comm::compax3LastErrorText(status.lastError)},
            {QStringLiteral("position"), status.position},
            {QStringLiteral("lastSet"), status.lastSet},
            {QStringLiteral("controlWord"), int(status.controlWord)},
            {QStringLiteral("summary"), status.summary()}};
}

}  // namespace

int runCompax3Info(CliSession& session, CommandArgs& args) {
    const bool json = args.takeFlag(QStringLiteral("--json"));
    if (const Status done = args.finish(); !done) return reportError(done.error());
    struct Info {
        Compax3Identity identity;
        Compax3DriveStatus status;
    };
    const Result<Info> info = runOnCompax3<Info>(
        session, QStringLiteral("c3 info"), [](Compax3Device& device, JobContext&) -> Result<Info> {
            const Result<Compax3Identity> identity = device.identity();
            if (!identity) return identity.error();
            const Result<Compax3DriveStatus> status = device.status();
            if (!status) return status.error();
            return Info{*identity, *status};
        });
    if (!info) return reportError(info.error());
    if (json)
        return printJson(
            QJsonDocument(QJsonObject{{QStringLiteral("family"), compax3FamilyId},
                                      {QStringLiteral("info"), info->identity.info},
                                      {QStringLiteral("serial"), info->identity.serial},
                                      {QStringLiteral("type"), info->identity.type()},
                                      {QStringLiteral("status"), statusJson(info->status)}}));
    printOut(QStringLiteral("family: compax3\ninfo: %1\nserial: %2\ntype: %3\naxis: %4\n"
                            "last error: %5\n")
                 .arg(info->identity.info, info->identity.serial, info->identity.type(),
                      info->status.summary(), comm::compax3LastErrorText(info->status.lastError)));
    return ExitOk;
}

int runCompax3Read(CliSession& session, CommandArgs& args, const Compax3Dictionary& dictionary) {
    const bool json = args.takeFlag(QStringLiteral("--json"));
    const bool hex = args.takeFlag(QStringLiteral("--hex"));
    const Result<QList<Compax3ObjectId>> ids = parseCompax3Objects(takeRest(args));
    if (!ids) return reportError(ids.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    for (const Compax3ObjectId& id : *ids)
        if (const Compax3ObjectInfo* info = dictionary.find(id); info && !info->readable())
            return reportError(
                Error::usage(QStringLiteral("%1 (%2) is a function: it is written, never read")
                                 .arg(id.text(), info->name)));
    const Result<QList<Reading>> values = runOnCompax3<QList<Reading>>(
        session, QStringLiteral("c3 read"), [ids = *ids, hex](Compax3Device& device, JobContext&) {
            return usecases::readCompax3Objects(device, ids, hex);
        });
    if (!values) return reportError(values.error());
    if (const Error refused = usecases::firstCompax3Refusal(*values);
        refused.kind != ErrorKind::None)
        return reportError(refused);
    if (json) {
        QJsonObject object;
        for (const Reading& reading : *values) object.insert(reading.id.text(), reading.value);
        return printJson(QJsonDocument(object));
    }
    QString text;
    for (const Reading& reading : *values)
        text += QStringLiteral("%1 = %2\n").arg(reading.id.text(), reading.value);
    printOut(text);
    return ExitOk;
}

int runCompax3Write(CliSession& session, CommandArgs& args, const Compax3Dictionary& dictionary) {
    // Every assignment checked before the first byte.
    QList<std::pair<Compax3ObjectId, QString>> writes;
    for (const QString& word : takeRest(args)) {
        const int equals = int(word.indexOf(QLatin1Char('=')));
        if (equals < 0)
            return reportError(Error::usage(
                QStringLiteral("c3 write needs OBJ=VALUE, e.g. 1901.1=12.5, not \"%1\"")
                    .arg(word)));
        const Result<Compax3ObjectId> id = parseCompax3Object(word.left(equals));
        if (!id) return reportError(id.error());
        // Whatever the dictionary in use says of it.
        if (compax3IsControlWord(dictionary, *id))
            return reportError(
                Error::usage(QStringLiteral("%1 is a control word, which moves the axis: use c3 "
                                            "enable, jog, move or stop")
                                 .arg(id->text())));
        const Result<QString> wire = compax3WireValueFor(dictionary, *id, word.mid(equals + 1));
        if (!wire) return reportError(wire.error());
        writes << std::pair{*id, *wire};
    }
    if (writes.isEmpty())
        return reportError(
            Error::usage(QStringLiteral("c3 write needs OBJ=VALUE, e.g. 1901.1=12.5")));
    if (const Status done = args.finish(); !done) return reportError(done.error());
    QString text;
    for (const auto& [id, wire] : writes) {
        const bool readBack = !dictionary.find(id) || dictionary.find(id)->readable();
        const Result<QString> back = runOnCompax3<QString>(
            session, QStringLiteral("c3 write"),
            [id = id, wire = wire, readBack](Compax3Device& device,
                                             JobContext&) -> Result<QString> {
                if (const Status written = device.writeObject(id, wire); !written)
                    return written.error();
                if (!readBack) return wire;
                return device.readObject(id, false);
            });
        if (!back) {
            printOut(text);
            return reportError(back.error());
        }
        text += QStringLiteral("%1 = %2\n").arg(id.text(), *back);
        if (readBack && !compax3SameValue(*back, wire)) {
            printOut(text);
            return reportError(Error::device(
                0,
                QStringLiteral("%1 reads back %2 after writing %3").arg(id.text(), *back, wire)));
        }
    }
    printOut(text);
    return ExitOk;
}

namespace {

int scanOn(CliSession& session, bool json) {
    session.setShowProgress(true);
    const Result<QList<int>> found = runOnCompax3<QList<int>>(
        session, QStringLiteral("c3 scan"), [](Compax3Device& device, JobContext& job) {
            return device.scanBus(0, comm::kCompax3LastAddress, [&job](qint64 done, qint64 total) {
                job.progress(done, total, QStringLiteral("scanning"));
            });
        });
    if (!found) return reportError(found.error());
    if (json) {
        QJsonArray array;
        for (int address : *found) array.append(address);
        return printJson(QJsonDocument(array));
    }
    QString text;
    for (int address : *found) text += QStringLiteral("%1\n").arg(address);
    if (found->isEmpty()) text = QStringLiteral("no drive answered at RS485 addresses 0..99\n");
    printOut(text);
    return ExitOk;
}

}  // namespace

int runCompax3Scan(CliSession& session, CommandArgs& args) {
    const bool json = args.takeFlag(QStringLiteral("--json"));
    if (const Status done = args.finish(); !done) return reportError(done.error());
    if (session.options().isBus()) return scanOn(session, json);
    // A scan is of RS485 addresses: the family's bus protocol, without
    // being told (the session has not opened the port yet).
    GlobalOptions onBus = session.options();
    onBus.protocol = QStringLiteral("compax3-rs485");
    CliSession bus(onBus);
    return scanOn(bus, json);
}

int runCompax3Status(CliSession& session, CommandArgs& args) {
    const bool json = args.takeFlag(QStringLiteral("--json"));
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<Compax3DriveStatus> status = runOnCompax3<Compax3DriveStatus>(
        session, QStringLiteral("c3 status"),
        [](Compax3Device& device, JobContext&) { return device.status(); });
    if (!status) return reportError(status.error());
    if (json) return printJson(QJsonDocument(statusJson(*status)));
    QString text = QStringLiteral("status word: %1\n").arg(compax3HexText(status->status.word, 4));
    for (const comm::Compax3StatusBit& bit : comm::compax3StatusBits(status->status.word))
        text += QStringLiteral("  b%1 %2: %3\n").arg(bit.bit).arg(bit.name).arg(bit.on ? 1 : 0);
    text += QStringLiteral("last error: %1\naxis: %2\n")
                .arg(comm::compax3LastErrorText(status->lastError), status->summary());
    printOut(text);
    return ExitOk;
}

int runCompax3Watch(CliSession& session, CommandArgs& args) {
    const Result<int> interval = args.takeIntOption(QStringLiteral("--interval"), 500, 0, 3600000);
    if (!interval) return reportError(interval.error());
    const Result<int> count = args.takeIntOption(QStringLiteral("--count"), 0, 0, 100000000);
    if (!count) return reportError(count.error());
    const Result<QList<Compax3ObjectId>> ids = parseCompax3Objects(takeRest(args));
    if (!ids) return reportError(ids.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    int failures = 0;
    for (int poll = 0; *count == 0 || poll < *count; ++poll) {
        if (poll > 0) QThread::msleep(ulong(*interval));
        Result<QList<Reading>> values = runOnCompax3<QList<Reading>>(
            session, QStringLiteral("c3 watch"), [ids = *ids](Compax3Device& device, JobContext&) {
                return usecases::readCompax3Objects(device, ids);
            });
        if (values)
            if (const Error refused = usecases::firstCompax3Refusal(*values);
                refused.kind != ErrorKind::None)
                values = refused;
        QStringList parts;
        for (int i = 0; i < ids->size(); ++i)
            parts << QStringLiteral("%1 = %2").arg(
                ids->at(i).text(), values ? values->at(i).value : QStringLiteral("? (no value)"));
        printOut(QStringLiteral("%1  %2\n")
                     .arg(QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss.zzz")),
                          parts.join(QStringLiteral("  "))));
        if (!values) {
            printError(values.error().message);
            // A usage error or a refusal does not go away by asking again.
            if (values.error().kind != ErrorKind::Communication || ++failures >= 3)
                return exitCodeFor(values.error().kind);
        } else {
            failures = 0;
        }
    }
    return ExitOk;
}

}  // namespace cambench::cli
