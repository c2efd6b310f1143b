// mc: the MC100/MC200 commands; the group's dispatch, its help, and info,
// var, flag and io.
#include "mc1_commands.h"

#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"
#include "model/mc1/mc1_family_id.h"

#include <QJsonArray>
#include <QJsonObject>

namespace cambench::cli {

namespace {

using comm::JobContext;
using comm::Mc1Device;
using comm::Mc1Point;

QString mc1Help() {
    return QStringLiteral(
        "  --variant auto|mc100v1|mc100v2|mc200v1|mc200v2   (default auto: probe it)\n"
        "  mc info [--json]                 controller, variant, how it was found, program\n"
        "  mc var read N[-M] [--json]       \"V12 = -5\" a line (24 bit MC100, 32 bit MC200)\n"
        "  mc var write N VALUE             writes, reads back, prints \"V12 = -5\"\n"
        "  mc flag read M… [--json]         \"M2327 = 1\" a line; also E122, A122\n"
        "  mc flag set|clear M…             flags and outputs, one WRBIT each, read back\n"
        "  mc io read [--json]              every input and output, \"E122 = 0\" a line\n"
        "  mc run|stop|step|reset           the PLC program (MC200 V2), then its status\n"
        "  mc flash save|load               the controller's flash (MC200 V2)\n"
        "  mc axis N status|home|stop|quickstop|ack [--json]\n"
        "  mc axis all stop                 every axis the controller has: the stops first,\n"
        "                                   then one line each: acknowledged, what reading\n"
        "                                   back found; exit 0 when every stop was acknowledged\n"
        "  mc axis N move --abs V | --rel V   starts a move (MC200 V2), prints the axis\n"
        "  mc axis N jog +|-                moves until `mc axis N stop`\n"
        "  mc axis N speed V                units per second\n"
        "  mc mem read ADDR LEN [-o FILE]   hex lines, or the bytes into FILE (MC200)\n"
        "  mc mem write ADDR HEX            e.g. mc mem write 0x1000 0a0b0c (MC200 V2)\n"
        "  mc backup -o FILE [--vars N-M] [--no-flags] [--mem ADDR:LEN]…\n"
        "                                   default: variables V1–V1000 and every external flag\n"
        "  mc verify FILE                   exit 0 equal, 1 the controller differs\n"
        "  mc restore FILE [--replacement]  checks FILE against the controller, writes only the\n"
        "                                   differences: written/unchanged/failed per item;\n"
        "                                   only to the controller FILE was taken from (variant,\n"
        "                                   axes, PLC program), else nothing is written (exit 4);\n"
        "                                   --replacement: this controller replaces that one\n"
        "  Options of every mc command:\n"
        "  --axes 1,2        the axes to use instead of finding them (MC200: RDTABLE per\n"
        "                    logical axis; an MC100 has no axis telegrams, so none)\n"
        "  --parameters FILE the controller's axis parameter numbers for RDSTAT, a CSV of\n"
        "                    name,axis,parameter lines (name position, target or status);\n"
        "                    without it CamBench's provisional guess is used and said\n"
        "  A command that acts (WRBIT, start, step, a move) is sent once: when its answer is\n"
        "  lost it exits 3 and says what reading back found. An acknowledged command is done\n"
        "  (exit 0) even when reading back fails; the output says so. A command of several\n"
        "  items (mc flag set M1 M2) checks them all before it sends anything.\n");
}

// --axes and --parameters: checked (the file read and parsed) before the
// connection opens, then handed to the device without a byte on the line.
Status applyMc1Options(CliSession& session, CommandArgs& args) {
    const Result<QString> axesText = args.takeOption(QStringLiteral("--axes"));
    if (!axesText) return axesText.error();
    const Result<QString> parametersPath = args.takeOption(QStringLiteral("--parameters"));
    if (!parametersPath) return parametersPath.error();
    std::optional<QList<int>> axes;
    if (!axesText->isEmpty()) {
        const Result<QList<int>> parsed = comm::parseMc1AxisList(*axesText);
        if (!parsed) return Error::usage(QStringLiteral("--axes: %1").arg(parsed.error().message));
        axes = *parsed;
    }
    std::optional<comm::Mc1AxisParameterTable> table;
    if (!parametersPath->isEmpty()) {
        const Result<comm::Mc1AxisParameterTable> parsed =
            comm::loadMc1AxisParameterTable(*parametersPath);
        if (!parsed)
            return Error::invalidData(QStringLiteral("--parameters %1 was not loaded: %2")
                                          .arg(*parametersPath, parsed.error().message));
        table = *parsed;
    }
    if (!axes && !table) return success();
    const Result<bool> applied =
        runOnMc1<bool>(session, QStringLiteral("mc options"),
                       [axes, table](Mc1Device& device, JobContext&) -> Result<bool> {
                           if (axes) device.setGivenAxes(axes);
                           if (table) device.setAxisParameters(*table);
                           return true;
                       });
    if (!applied) return applied.error();
    return success();
}

int runMc(CliSession& session, CommandArgs& args) {
    if (const Status applied = applyMc1Options(session, args); !applied)
        return reportError(applied.error());
    const Result<QString> verb =
        takeVerb(args, {QStringLiteral("info"), QStringLiteral("var"), QStringLiteral("flag"),
                        QStringLiteral("io"), QStringLiteral("run"), QStringLiteral("stop"),
                        QStringLiteral("step"), QStringLiteral("reset"), QStringLiteral("flash"),
                        QStringLiteral("axis"), QStringLiteral("mem"), QStringLiteral("backup"),
                        QStringLiteral("verify"), QStringLiteral("restore")});
    if (!verb) return reportError(verb.error());
    if (*verb == QLatin1String("info")) return runMc1Info(session, args);
    if (*verb == QLatin1String("var")) return runMc1Variables(session, args);
    if (*verb == QLatin1String("flag")) return runMc1Points(session, args, false);
    if (*verb == QLatin1String("io")) return runMc1Points(session, args, true);
    if (*verb == QLatin1String("axis")) return runMc1Axis(session, args);
    if (*verb == QLatin1String("mem")) return runMc1Memory(session, args);
    if (*verb == QLatin1String("backup")) return runMc1Backup(session, args);
    if (*verb == QLatin1String("verify")) return runMc1Verify(session, args);
    if (*verb == QLatin1String("restore")) return runMc1Restore(session, args);
    return runMc1Program(session, args, *verb);
}

QString pointLine(const Mc1Point& point, bool on) {
    return QStringLiteral("%1 = %2\n").arg(comm::mc1PointText(point)).arg(on ? 1 : 0);
}

int printPoints(const QList<Mc1Point>& points, const QList<bool>& values, bool json) {
    if (json) {
        QJsonObject object;
        for (int i = 0; i < points.size(); ++i)
            object.insert(comm::mc1PointText(points.at(i)), values.at(i) ? 1 : 0);
        return printJson(QJsonDocument(object));
    }
    QString text;
    for (int i = 0; i < points.size(); ++i) text += pointLine(points.at(i), values.at(i));
    printOut(text);
    return ExitOk;
}

}  // namespace

Result<std::pair<int, int>> parseMc1Range(const QString& text, const QString& what, int min,
                                          int max) {
    const QStringList parts = text.split(QLatin1Char('-'));
    if (parts.size() > 2 || text.isEmpty())
        return Error::usage(QStringLiteral("%1 must be N or N-M, not \"%2\"").arg(what, text));
    const Result<int> first = parseIntArgument(parts.first(), what, min, max);
    if (!first) return first.error();
    const Result<int> last = parseIntArgument(parts.last(), what, *first, max);
    if (!last) return last.error();
    return std::pair<int, int>{*first, *last};
}

Result<int> parseMc1Address(const QString& text, const QString& what, int max) {
    bool ok = false;
    const int value = text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)
                          ? text.mid(2).toInt(&ok, 16)
                          : text.toInt(&ok, 10);
    if (!ok || value < 0 || value > max)
        return Error::usage(QStringLiteral("%1 must be 0 to 0x%2 (decimal or 0x hex), not \"%3\"")
                                .arg(what)
                                .arg(max, 0, 16)
                                .arg(text));
    return value;
}

int runMc1Info(CliSession& session, CommandArgs& args) {
    const bool json = args.takeFlag(QStringLiteral("--json"));
    if (const Status done = args.finish(); !done) return reportError(done.error());
    struct Info {
        comm::Mc1Variant variant;
        QString source;
        std::optional<comm::Mc1ProgramStatus> program;
        QStringList capabilities;
    };
    const Result<Info> info =
        runOnMc1<Info>(session, QStringLiteral("mc info"), [](Mc1Device& device, JobContext&) {
            const Result<comm::Mc1Variant> variant = device.ensureIdentified();
            if (!variant) return Result<Info>(variant.error());
            Info info{*variant, device.variantSource(), std::nullopt, {}};
            const std::pair<comm::Mc1Capability, const char*> names[] = {
                {comm::Mc1Capability::BlockRead, "block-read"},
                {comm::Mc1Capability::MemoryRead, "memory-read"},
                {comm::Mc1Capability::MemoryWrite, "memory-write"},
                {comm::Mc1Capability::ProgramControl, "program-control"},
                {comm::Mc1Capability::Axes, "axes"}};
            for (const auto& [capability, name] : names)
                if (device.has(capability)) info.capabilities << QLatin1String(name);
            if (device.has(comm::Mc1Capability::ProgramControl)) {
                const Result<comm::Mc1ProgramStatus> status = device.programStatus();
                if (!status) return Result<Info>(status.error());
                info.program = *status;
            }
            return Result<Info>(info);
        });
    if (!info) return reportError(info.error());
    const QList<std::pair<QString, QString>> lines{
        {QStringLiteral("family"), mc1FamilyId},
        {QStringLiteral("variant"), comm::mc1VariantName(info->variant)},
        {QStringLiteral("variantKey"), comm::mc1VariantKey(info->variant)},
        {QStringLiteral("found"), info->source},
        {QStringLiteral("variableBits"), QString::number(comm::mc1VariableBits(info->variant))},
        {QStringLiteral("capabilities"), info->capabilities.join(QLatin1Char(','))},
        {QStringLiteral("program"),
         info->program ? info->program->summary() : QStringLiteral("(not readable)")},
    };
    if (json) {
        QJsonObject object;
        for (const auto& [key, value] : lines) object.insert(key, value);
        if (info->program) {
            object.insert(QStringLiteral("programCounter"), info->program->programCounter);
            object.insert(QStringLiteral("programFlags"),
                          QJsonArray::fromStringList(info->program->flagTexts()));
        }
        return printJson(QJsonDocument(object));
    }
    QString text;
    for (const auto& [key, value] : lines) text += QStringLiteral("%1: %2\n").arg(key, value);
    printOut(text);
    return ExitOk;
}

int runMc1Variables(CliSession& session, CommandArgs& args) {
    const Result<QString> verb = takeVerb(args, {QStringLiteral("read"), QStringLiteral("write")});
    if (!verb) return reportError(verb.error());
    const bool json = args.takeFlag(QStringLiteral("--json"));
    const Result<QString> first = args.takeRequiredPositional(QStringLiteral("a variable N"));
    if (!first) return reportError(first.error());
    if (*verb == QLatin1String("read")) {
        if (const Status done = args.finish(); !done) return reportError(done.error());
        const Result<std::pair<int, int>> range =
            parseMc1Range(*first, QStringLiteral("variable"), 0, 0xFFFF);
        if (!range) return reportError(range.error());
        session.setShowProgress(range->second > range->first);
        const Result<QList<qint64>> values = runOnMc1<QList<qint64>>(
            session, QStringLiteral("mc var read"),
            [range = *range](Mc1Device& device, JobContext& job) -> Result<QList<qint64>> {
                QList<qint64> values;
                for (int n = range.first; n <= range.second; ++n) {
                    if (job.cancelled()) return Error::cancelled();
                    const Result<qint64> value = device.readVariable(n);
                    if (!value) return value.error();
                    values << *value;
                    job.progress(n - range.first + 1, range.second - range.first + 1,
                                 QStringLiteral("reading variables"));
                }
                return values;
            });
        if (!values) return reportError(values.error());
        if (json) {
            QJsonObject object;
            for (int i = 0; i < values->size(); ++i)
                object.insert(QStringLiteral("V%1").arg(range->first + i), values->at(i));
            return printJson(QJsonDocument(object));
        }
        QString text;
        for (int i = 0; i < values->size(); ++i)
            text += QStringLiteral("V%1 = %2\n").arg(range->first + i).arg(values->at(i));
        printOut(text);
        return ExitOk;
    }
    const Result<int> number = parseIntArgument(*first, QStringLiteral("variable"), 0, 0xFFFF);
    if (!number) return reportError(number.error());
    const Result<QString> valueText = args.takeRequiredPositional(QStringLiteral("a VALUE"));
    if (!valueText) return reportError(valueText.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    bool ok = false;
    const qint64 value = valueText->toLongLong(&ok);
    if (!ok)
        return reportError(Error::usage(
            QStringLiteral("VALUE must be a whole number, not \"%1\"").arg(*valueText)));
    const Result<qint64> back =
        runOnMc1<qint64>(session, QStringLiteral("mc var write"),
                         [n = *number, value](Mc1Device& device, JobContext&) -> Result<qint64> {
                             if (const Status written = device.writeVariable(n, value); !written)
                                 return written.error();
                             return device.readVariable(n);
                         });
    if (!back) return reportError(back.error());
    printOut(QStringLiteral("V%1 = %2\n").arg(*number).arg(*back));
    if (*back != value)
        return reportError(Error::device(0, QStringLiteral("V%1 reads back %2, not the %3 written")
                                                .arg(*number)
                                                .arg(*back)
                                                .arg(value)));
    return ExitOk;
}

int runMc1Points(CliSession& session, CommandArgs& args, bool io) {
    const Result<QString> verb = io ? Result<QString>(QStringLiteral("read"))
                                    : takeVerb(args, {QStringLiteral("read"), QStringLiteral("set"),
                                                      QStringLiteral("clear")});
    if (io) {
        if (const Result<QString> read = takeVerb(args, {QStringLiteral("read")}); !read)
            return reportError(read.error());
    }
    if (!verb) return reportError(verb.error());
    const bool json = args.takeFlag(QStringLiteral("--json"));
    QList<Mc1Point> points;
    for (QString word = args.takePositional(); !word.isEmpty(); word = args.takePositional()) {
        if (word.at(0).isDigit()) word.prepend(QLatin1Char('M'));  // a bare number is a flag
        const Result<Mc1Point> point = comm::parseMc1Point(word);
        if (!point) return reportError(point.error());
        points << *point;
    }
    if (const Status done = args.finish(); !done) return reportError(done.error());
    if (!io && points.isEmpty())
        return reportError(Error::usage(
            QStringLiteral("mc flag %1 needs flags, inputs or outputs: M2327 E122 A122")
                .arg(*verb)));
    if (io || *verb == QLatin1String("read")) {
        struct Read {
            QList<Mc1Point> points;
            QList<bool> values;
        };
        session.setShowProgress(io);
        const Result<Read> read = runOnMc1<Read>(
            session, QStringLiteral("mc read"),
            [points, io](Mc1Device& device, JobContext& job) -> Result<Read> {
                QList<Mc1Point> asked = points;
                if (io) {
                    const Result<comm::Mc1Variant> variant = device.ensureIdentified();
                    if (!variant) return variant.error();
                    for (comm::Mc1Area area : {comm::Mc1Area::Input, comm::Mc1Area::Output})
                        for (int n : comm::mc1PointNumbers(area, comm::isMc200(*variant)))
                            asked << Mc1Point{area, n};
                }
                const Result<QList<bool>> values =
                    device.readPoints(asked, [&job](qint64 done, qint64 total) {
                        job.progress(done, total, QStringLiteral("reading"));
                    });
                if (!values) return values.error();
                return Read{asked, *values};
            });
        if (!read) return reportError(read.error());
        return printPoints(read->points, read->values, json);
    }
    const bool on = *verb == QLatin1String("set");
    // Every point is checked against the controller before the first one
    // is written; then they are written in order until one fails.
    struct Written {
        QString text;
        std::optional<Error> error;
    };
    const Result<Written> written = runOnMc1<Written>(
        session, QStringLiteral("mc flag"),
        [points, on](Mc1Device& device, JobContext&) -> Result<Written> {
            const Result<comm::Mc1Variant> variant = device.ensureIdentified();
            if (!variant) return variant.error();
            for (const Mc1Point& point : points)
                if (const Status ok = comm::mc1CheckWritable(point, *variant); !ok)
                    return Error::usage(
                        QStringLiteral("%1; nothing was written").arg(ok.error().message));
            Written done;
            for (const Mc1Point& point : points) {
                const Result<bool> back = device.writePoint(point, on);
                if (!back) {
                    done.error = back.error();
                    return done;
                }
                done.text += pointLine(point, *back);
                if (*back != on) {
                    done.error = Error::device(0, QStringLiteral("%1 reads back %2 after the write")
                                                      .arg(comm::mc1PointText(point))
                                                      .arg(*back ? 1 : 0));
                    return done;
                }
            }
            return done;
        });
    if (!written) return reportError(written.error());
    printOut(written->text);
    if (written->error) return reportError(*written->error);
    return ExitOk;
}

void registerMc1Commands(FamilyCommands& commands) {
    commands.add(QStringLiteral("mc"), runMc);
    // applyMc1Options takes them, wherever they stood on the line.
    commands.addOption(QStringLiteral("--axes"));
    commands.addOption(QStringLiteral("--parameters"));
    commands.addHelp(mc1Help());
}

}  // namespace cambench::cli
