// c3: the Compax3 commands; the group's dispatch and its help.
#include "compax3_commands.h"

#include "app/cli/cli_output.h"

namespace cambench::cli {

namespace {

QString compax3Help() {
    return QStringLiteral(
        "  --address N (RS485, implies --protocol compax3-rs485); c3 commands take\n"
        "  --dictionary FILE: your own object dictionary instead of the shipped one\n"
        "  c3 info [--json]                 info string, serial number, type, axis, last error\n"
        "  c3 read OBJ… [--hex] [--json]    \"680.5 = 12.5\" a line; OBJ as 680.5, o680.5 or\n"
        "                                   \"O 680,5\" ($ for hexadecimal numbers)\n"
        "  c3 write OBJ=VALUE…              checked against the dictionary first, then written\n"
        "                                   and read back; a refusal exits 1 with the drive's "
        "!xxxx\n"
        "  c3 scan [--json]                 RS485 addresses 0..99 that answer, one a line\n"
        "                                   (on RS485 without --protocol or --address)\n"
        "  c3 status [--json]               status word bit by bit, last error, position\n"
        "  c3 watch OBJ… [--interval MS] [--count N]   the values, a line per poll\n"
        "  c3 enable|disable|stop           power and acknowledge, powerless, stop with the ramp\n"
        "                                   (stop sends nothing to a powerless drive)\n"
        "  c3 jog +|-                       moves until `c3 stop`\n"
        "  c3 move N [--target V] [--velocity V] [--accel V] [--decel V]\n"
        "                                   writes what is given into set N, then starts it\n"
        "  c3 backup -o FILE [--objects LIST]   default: every read-write object of the\n"
        "                                   dictionary; the drive's identity and a SHA-256;\n"
        "                                   objects the drive lacks are recorded as not on\n"
        "                                   it (exit 0); control words and functions are\n"
        "                                   never saved\n"
        "  c3 verify FILE                   exit 0 equal, 1 the drive differs\n"
        "  c3 restore FILE [--replacement] [--force] [--only LIST] [--store]\n"
        "                                   only to the drive FILE was read from (serial number\n"
        "                                   and type), else nothing is written (exit 4);\n"
        "                                   --replacement: this drive replaces that one;\n"
        "                                   writes what differs: written/unchanged/failed per\n"
        "                                   object; --force: a file of another drive type;\n"
        "                                   --store: then stores each set (1904.n = $32);\n"
        "                                   a control word or function in the file: nothing\n"
        "                                   is sent to it, and it is said\n"
        "  A command that moves the axis is sent once: when its answer is lost it exits 3 and\n"
        "  says what reading back found. Acknowledged is done: a read-back that fails\n"
        "  afterwards is a note (exit 0). enable sends nothing to a powered drive.\n");
}

int runC3(CliSession& session, CommandArgs& args) {
    const Result<QString> dictionaryPath = args.takeOption(QStringLiteral("--dictionary"));
    if (!dictionaryPath) return reportError(dictionaryPath.error());
    Compax3Dictionary dictionary = Compax3Dictionary::builtin();
    if (!dictionaryPath->isEmpty()) {
        const Result<Compax3Dictionary> loaded = Compax3Dictionary::load(*dictionaryPath);
        if (!loaded) return reportError(loaded.error());
        dictionary = *loaded;
    }
    const Result<QString> verb =
        takeVerb(args, {QStringLiteral("info"), QStringLiteral("read"), QStringLiteral("write"),
                        QStringLiteral("scan"), QStringLiteral("watch"), QStringLiteral("status"),
                        QStringLiteral("enable"), QStringLiteral("disable"), QStringLiteral("stop"),
                        QStringLiteral("jog"), QStringLiteral("move"), QStringLiteral("backup"),
                        QStringLiteral("verify"), QStringLiteral("restore")});
    if (!verb) return reportError(verb.error());
    // The drive's refusals are worded by the dictionary given (scan talks
    // to several drives and reads only their identity).
    if (!dictionaryPath->isEmpty() && *verb != QLatin1String("scan")) {
        const Result<bool> used = runOnCompax3<bool>(
            session, QStringLiteral("c3 dictionary"),
            [dictionary](comm::Compax3Device& device, comm::JobContext&) -> Result<bool> {
                device.setDictionary(dictionary);
                return true;
            });
        if (!used) return reportError(used.error());
    }
    if (*verb == QLatin1String("info")) return runCompax3Info(session, args);
    if (*verb == QLatin1String("read")) return runCompax3Read(session, args, dictionary);
    if (*verb == QLatin1String("write")) return runCompax3Write(session, args, dictionary);
    if (*verb == QLatin1String("scan")) return runCompax3Scan(session, args);
    if (*verb == QLatin1String("watch")) return runCompax3Watch(session, args);
    if (*verb == QLatin1String("status")) return runCompax3Status(session, args);
    if (*verb == QLatin1String("backup")) return runCompax3Backup(session, args, dictionary);
    if (*verb == QLatin1String("verify")) return runCompax3Verify(session, args, dictionary);
    if (*verb == QLatin1String("restore")) return runCompax3Restore(session, args, dictionary);
    return runCompax3Motion(session, args, *verb);
}

}  // namespace

Result<QList<Compax3ObjectId>> parseCompax3Objects(const QStringList& words) {
    QList<Compax3ObjectId> ids;
    QStringList joined;  // `c3 read O 680,5` unquoted: "O" and "680,5" are one object
    for (const QString& word : words) {
        if (!joined.isEmpty() &&
            joined.last().compare(QLatin1String("O"), Qt::CaseInsensitive) == 0)
            joined.last() += word;
        else
            joined << word;
    }
    for (const QString& word : joined) {
        // "O 680,5" is one object; "680.5,1901.1" two.
        const QStringList parts = word.trimmed().startsWith(QLatin1Char('O'), Qt::CaseInsensitive)
                                      ? QStringList{word}
                                      : word.split(QLatin1Char(','), Qt::SkipEmptyParts);
        for (const QString& part : parts) {
            const Result<Compax3ObjectId> id = parseCompax3Object(part);
            if (!id) return id.error();
            ids << *id;
        }
    }
    if (ids.isEmpty()) return Error::usage(QStringLiteral("no object given; write e.g. 680.5"));
    return ids;
}

void registerCompax3Commands(FamilyCommands& commands) {
    commands.add(QStringLiteral("c3"), runC3);
    // runC3 takes it, wherever it stood on the line.
    commands.addOption(QStringLiteral("--dictionary"));
    commands.addHelp(compax3Help());
}

}  // namespace cambench::cli
