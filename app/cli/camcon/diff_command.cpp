// diff A B: what differs between the cam programs of two sources - project
// files, CSV cam files or the device - one difference a line; exit 0 when
// equal, 1 when they differ. With --git it is git's external diff driver
// for every CamBench file (README: "CamBench files under git"); --git-setup
// prints the lines that install it.
#include "app/cli/camcon/camcon_commands.h"
#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"

#include "comm/camcon/usecases/program_read.h"
#include "model/camcon/csv_io.h"
#include "model/camcon/eeprom_image_file.h"
#include "model/camcon/program_diff.h"
#include "model/camcon/project_content.h"
#include "model/camcon/project_file.h"
#include "model/file_differences.h"
#include "model/file_read.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

namespace cambench::cli {

namespace {

using comm::CamConDevice;
using comm::JobContext;

constexpr int kMaxProgramNumber = 32767;  // as cams read
const QString kDevice = QStringLiteral("device");

// One side of the comparison: its programs by number. A CSV file holds one
// program without a name; the device's program is read with its name.
struct Side {
    QString label;
    QMap<int, CamProgram> programs;
    bool named = true;
    bool single = false;  // one program, whatever its number (a CSV file)
};

bool isCsv(const QString& path) {
    return QFileInfo(path).suffix().compare(QLatin1String("csv"), Qt::CaseInsensitive) == 0;
}

// A CamCon backup (an EEPROM image) rather than a project file.
bool isBackup(const QString& path) {
    const Result<QByteArray> bytes = readFileBytes(path);
    return bytes && QJsonDocument::fromJson(*bytes).object().value(QStringLiteral("format")) ==
                        QLatin1String("cambench-eeprom-image");
}

// The programs a backup holds decoded beside its blocks.
Result<Project> backupProject(const QString& path) {
    const Result<EepromImage> image = loadEepromImage(path);
    if (!image) return image.error();
    if (image->content.isEmpty())
        return Error::invalidData(
            QStringLiteral("%1 is a backup of the older format: its blocks are not decoded, so "
                           "its cams cannot be compared. Compare it with the device (`verify "
                           "%1`) or take a new backup")
                .arg(path));
    return projectFromContent(image->content, image->device);
}

Result<Side> loadFile(const QString& path, const QString& kindFrom) {
    Side side;
    side.label = path;
    if (isCsv(kindFrom)) {
        side.named = false;
        side.single = true;
        if (path == QLatin1String("/dev/null")) return side;  // git: the file is new or gone
        const Result<Tracks> tracks = loadCamsCsv(path);
        if (!tracks) return tracks.error();
        CamProgram program;
        program.tracks = *tracks;
        side.programs.insert(0, program);
        return side;
    }
    if (path == QLatin1String("/dev/null")) return side;
    const Result<Project> project = isBackup(path) ? backupProject(path) : loadProject(path);
    if (!project) return project.error();
    for (const CamProgram& program : project->programs)
        side.programs.insert(program.number, program);
    return side;
}

Result<Side> readDevice(CliSession& session, int program) {
    session.setShowProgress(true);
    const Result<CamProgram> read = runOnCamCon<CamProgram>(
        session, QStringLiteral("diff"),
        [program](CamConDevice& device, JobContext& job) -> Result<CamProgram> {
            Result<usecases::ProgramRead> fetched = usecases::readIdentityAndProgram(
                device, program, usecases::UseCaseProgress::of(job));
            if (!fetched) return fetched.error();
            return std::move(fetched->program);
        });
    if (!read) return read.error();
    Side side;
    side.label = session.where();
    side.programs.insert(program, *read);
    return side;
}

// The program `number` of `side`: a CSV file's one program stands for any.
std::optional<CamProgram> programOf(const Side& side, int number) {
    if (side.single) {
        if (side.programs.isEmpty()) return CamProgram{};
        return side.programs.first();
    }
    if (!side.programs.contains(number)) return std::nullopt;
    return side.programs.value(number);
}

struct Line {
    int program;
    QString text;
    QJsonObject json;
};

QJsonObject camJson(const Cam& cam) {
    return {{QStringLiteral("on"), cam.on}, {QStringLiteral("off"), cam.off}};
}

void addProgramDiff(int numberA, int numberB, const CamProgram& a, const CamProgram& b,
                    bool compareNames, QList<Line>& lines) {
    ProgramDiff diff = diffPrograms(a, b);
    const QJsonObject where{{QStringLiteral("programA"), numberA},
                            {QStringLiteral("programB"), numberB}};
    if (compareNames && diff.nameDiffers()) {
        QJsonObject json = where;
        json.insert(QStringLiteral("kind"), QStringLiteral("name"));
        json.insert(QStringLiteral("a"), diff.nameA);
        json.insert(QStringLiteral("b"), diff.nameB);
        lines.append(
            {numberA, QStringLiteral("name \"%1\" → \"%2\"").arg(diff.nameA, diff.nameB), json});
    }
    static const char* const kinds[] = {"onlyInA", "onlyInB", "changed"};
    for (const CamDifference& cam : diff.cams) {
        QJsonObject json = where;
        json.insert(QStringLiteral("kind"), QLatin1String(kinds[int(cam.kind)]));
        json.insert(QStringLiteral("output"), cam.output);
        if (cam.camA > 0) {
            json.insert(QStringLiteral("camA"), cam.camA);
            json.insert(QStringLiteral("a"), camJson(cam.a));
        }
        if (cam.camB > 0) {
            json.insert(QStringLiteral("camB"), cam.camB);
            json.insert(QStringLiteral("b"), camJson(cam.b));
        }
        lines.append({numberA, describeDifference(cam), json});
    }
}

// Every program either side holds, or the one chosen.
Result<QList<Line>> compare(const Side& a, const Side& b, int programA, int programB) {
    QList<Line> lines;
    const bool names = a.named && b.named;
    if (programA >= 0) {
        const std::optional<CamProgram> pa = programOf(a, programA);
        const std::optional<CamProgram> pb = programOf(b, programB);
        for (const auto& [side, program, found] :
             {std::tuple{&a, programA, pa.has_value()}, std::tuple{&b, programB, pb.has_value()}}) {
            if (!found)
                return Error::invalidData(QStringLiteral("%1 holds no program %2 (not read or not "
                                                         "there); choose another --program")
                                              .arg(side->label)
                                              .arg(program));
        }
        addProgramDiff(programA, programB, *pa, *pb, names, lines);
        return lines;
    }
    if (a.single != b.single && !(a.programs.isEmpty() || b.programs.isEmpty()))
        return Error::usage(
            QStringLiteral("a CSV file holds one program: add --program P to choose the "
                           "program of the project to compare it with"));
    QList<int> numbers = a.programs.keys() + b.programs.keys();
    std::sort(numbers.begin(), numbers.end());
    numbers.erase(std::unique(numbers.begin(), numbers.end()), numbers.end());
    if (a.single && b.single) numbers = {0};
    for (int number : numbers) {
        const std::optional<CamProgram> pa = programOf(a, number);
        const std::optional<CamProgram> pb = programOf(b, number);
        if (pa && pb) {
            addProgramDiff(number, number, *pa, *pb, names, lines);
            continue;
        }
        // A program only one side holds (the other never read it, or lacks it).
        const bool inA = pa.has_value();
        lines.append({number,
                      inA ? QStringLiteral("only in A") : QStringLiteral("only in B"),
                      {{QStringLiteral("programA"), number},
                       {QStringLiteral("programB"), number},
                       {QStringLiteral("kind"), inA ? QStringLiteral("programOnlyInA")
                                                    : QStringLiteral("programOnlyInB")}}});
    }
    return lines;
}

QString text(const QList<Line>& lines, bool oneProgram) {
    QString out;
    for (const Line& line : lines) {
        out += oneProgram ? line.text
                          : QStringLiteral("program %1: %2").arg(line.program).arg(line.text);
        out += QLatin1Char('\n');
    }
    return out;
}

// The bytes of one side for the git driver: git passes /dev/null for a
// file that is new or gone; a file that cannot be read is said.
QByteArray gitSideBytes(const QString& file, QStringList& notes) {
    if (file == QLatin1String("/dev/null")) return {};
    const Result<QByteArray> bytes = readFileBytes(file);
    if (!bytes) {
        notes << QStringLiteral("cannot read %1: %2").arg(file, bytes.error().message);
        return {};
    }
    return *bytes;
}

// A JSON document's top value; an empty side (new or gone) is an empty
// object. Nullopt for bytes that are not JSON.
std::optional<QJsonValue> jsonOf(const QByteArray& bytes) {
    if (bytes.trimmed().isEmpty()) return QJsonValue(QJsonObject());
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(bytes, &error);
    if (error.error != QJsonParseError::NoError) return std::nullopt;
    if (document.isArray()) return QJsonValue(document.array());
    return QJsonValue(document.object());
}

// What differs between the two versions of `path`: the cam programs of
// CamCon projects and cam CSV files, then for any JSON file (projects,
// EEPROM images, settings, machine files, the other families' backups)
// each member that differs, for anything else the lines. Never fails.
QString gitDifferences(const QString& path, const QString& fileA, const QString& fileB) {
    QStringList notes;
    const QByteArray bytesA = gitSideBytes(fileA, notes);
    const QByteArray bytesB = gitSideBytes(fileB, notes);
    QString out = notes.isEmpty() ? QString() : notes.join(u'\n') + u'\n';
    const Result<Side> a = loadFile(fileA, path);
    const Result<Side> b = loadFile(fileB, path);
    bool camsShown = false;
    if (a && b) {
        const Result<QList<Line>> lines = compare(*a, *b, -1, -1);
        if (lines) {
            out += lines->isEmpty() ? QStringLiteral("no cam program differs\n")
                                    : text(*lines, a->single && b->single);
            camsShown = true;
        }
    }
    if (camsShown && isCsv(path)) return out;
    const std::optional<QJsonValue> jsonA = jsonOf(bytesA);
    const std::optional<QJsonValue> jsonB = jsonOf(bytesB);
    if (jsonA && jsonB) {
        // The cam programs were compared above; the rest member by member.
        const QStringList members = jsonDifferences(
            *jsonA, *jsonB, camsShown ? QStringList{QStringLiteral("programs")} : QStringList{});
        if (camsShown && !members.isEmpty()) out += QStringLiteral("and besides the cams:\n");
        for (const QString& line : members) out += line + u'\n';
        if (!camsShown && members.isEmpty()) out += QStringLiteral("no difference\n");
        return out;
    }
    const QString lines = textDifferences(QString::fromUtf8(bytesA), QString::fromUtf8(bytesB));
    return out + (lines.isEmpty() ? QStringLiteral("no difference\n") : lines);
}

// git's external diff driver: PATH OLD-FILE OLD-HEX OLD-MODE NEW-FILE NEW-HEX NEW-MODE.
// Git stops on a non-zero exit, so differences exit 0 here, and so does a
// file it cannot make sense of (shown as text).
int runGitDriver(CommandArgs& args) {
    QStringList parts;
    for (QString part = args.takePositional(); !part.isEmpty(); part = args.takePositional())
        parts << part;
    if (parts.size() != 7)
        return reportError(Error::usage(QStringLiteral(
            "diff --git takes the 7 arguments git passes to an external diff driver")));
    const QString& path = parts.at(0);
    printOut(QStringLiteral("cambench diff %1\n").arg(path) +
             gitDifferences(path, parts.at(1), parts.at(4)));
    return ExitOk;
}

// A word as the shell reads it back: quoted unless it is plain.
QString shellQuoted(const QString& word) {
    static const QRegularExpression plain(QStringLiteral("^[A-Za-z0-9_./+-]+$"));
    if (plain.match(word).hasMatch()) return word;
    return QStringLiteral("'%1'").arg(QString(word).replace(u'\'', QLatin1String("'\\''")));
}

// The lines that make this cambench-cli git's diff driver for CamBench's
// files, with its absolute path: git runs it without PATH.
int runGitSetup(CommandArgs& args) {
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const QString command =
        shellQuoted(QCoreApplication::applicationFilePath()) + QStringLiteral(" diff --git");
    printOut(QStringLiteral("echo '*.json diff=cambench' >> .gitattributes\n"
                            "echo '*.csv diff=cambench' >> .gitattributes\n"
                            "git config diff.cambench.command %1\n")
                 .arg(shellQuoted(command)));
    return ExitOk;
}

}  // namespace

int runDiff(CliSession& session, CommandArgs& args) {
    if (args.takeFlag(QStringLiteral("--git"))) return runGitDriver(args);
    if (args.takeFlag(QStringLiteral("--git-setup"))) return runGitSetup(args);
    const bool json = args.takeFlag(QStringLiteral("--json"));
    const Result<int> program =
        args.takeIntOption(QStringLiteral("--program"), -1, 0, kMaxProgramNumber);
    if (!program) return reportError(program.error());
    const Result<int> programB =
        args.takeIntOption(QStringLiteral("--program-b"), -1, 0, kMaxProgramNumber);
    if (!programB) return reportError(programB.error());
    const Result<QString> first =
        args.takeRequiredPositional(QStringLiteral("A (a FILE or device)"));
    if (!first) return reportError(first.error());
    const Result<QString> second =
        args.takeRequiredPositional(QStringLiteral("B (a FILE or device)"));
    if (!second) return reportError(second.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    if (*programB >= 0 && *program < 0)
        return reportError(Error::usage(QStringLiteral("--program-b needs --program for A")));
    const int pa = *program;
    const int pb = *programB >= 0 ? *programB : pa;

    // Both files first: a typo in a path is said before the device is asked.
    std::optional<Side> sides[2];
    const QString sources[2] = {*first, *second};
    for (int i = 0; i < 2; ++i) {
        if (sources[i] == kDevice) continue;
        const Result<Side> side = loadFile(sources[i], sources[i]);
        if (!side) return reportError(side.error());
        sides[i] = *side;
    }
    for (int i = 0; i < 2; ++i) {
        if (sources[i] != kDevice) continue;
        if (pa < 0)
            return reportError(
                Error::usage(QStringLiteral("diff with the device needs --program P")));
        const Result<Side> side = readDevice(session, i == 0 ? pa : pb);
        if (!side) return reportError(side.error());
        sides[i] = *side;
    }
    const Result<QList<Line>> lines = compare(*sides[0], *sides[1], pa, pb);
    if (!lines) return reportError(lines.error());
    const int exit = lines->isEmpty() ? ExitOk : ExitDevice;
    if (json) {
        QJsonArray differences;
        for (const Line& line : *lines) {
            QJsonObject entry = line.json;
            entry.insert(QStringLiteral("text"), line.text);
            differences.append(entry);
        }
        printJson(QJsonDocument(QJsonObject{{QStringLiteral("a"), sides[0]->label},
                                            {QStringLiteral("b"), sides[1]->label},
                                            {QStringLiteral("equal"), lines->isEmpty()},
                                            {QStringLiteral("differences"), differences}}));
        return exit;
    }
    printOut(text(*lines, pa >= 0 || (sides[0]->single && sides[1]->single)));
    return exit;
}

}  // namespace cambench::cli
