#include "machine_bench.h"

#include "bench_process.h"
#include "model/camcon/camcon_family_id.h"
#include "model/compax3/compax3_family_id.h"
#include "model/mc1/mc1_family_id.h"
#include "tests/e2e/child_process.h"

#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTextStream>

#include <algorithm>
#include <memory>
#include <vector>

namespace cambench::bench {

namespace {

struct Device {
    QString name;
    QString family;
    QStringList simArgs;  // besides --baud
    QJsonObject entry;    // its machine file entry, the port filled in once started
};

QList<Device> devices(int baud) {
    const auto entry = [baud](const QString& name, const QString& family) {
        return QJsonObject{{QStringLiteral("name"), name},
                           {QStringLiteral("family"), family},
                           {QStringLiteral("baud"), baud}};
    };
    QJsonObject plc = entry(QStringLiteral("plc"), mc1FamilyId);
    plc.insert(QStringLiteral("protocol"), QStringLiteral("mc1"));
    plc.insert(QStringLiteral("variant"), QStringLiteral("mc200v2"));
    return {{QStringLiteral("cams"),
             camconFamilyId,
             {QStringLiteral("--eprom"), QStringLiteral("03.05.2001"), QStringLiteral("--fill"),
              QStringLiteral("1")},
             entry(QStringLiteral("cams"), camconFamilyId)},
            {QStringLiteral("plc"),
             mc1FamilyId,
             {QStringLiteral("--protocol"), QStringLiteral("mc1"), QStringLiteral("--variant"),
              QStringLiteral("mc200v2")},
             plc},
            {QStringLiteral("feed"),
             compax3FamilyId,
             {QStringLiteral("--protocol"), QStringLiteral("compax3"),
              QStringLiteral("--drive-type"), QStringLiteral("S150V4")},
             entry(QStringLiteral("feed"), compax3FamilyId)}};
}

// Seconds of one `machine backup` of `entries` into `name`-backup, or with
// `into` (--archive DIR ...) as given; a failed backup is fatal (a figure
// of a failed run would say nothing).
double timeBackup(const QTemporaryDir& dir, const QString& name, const QJsonArray& entries,
                  const QStringList& into = {}) {
    const QString file = dir.filePath(name + QStringLiteral(".json"));
    QFile out(file);
    if (!out.open(QIODevice::WriteOnly) ||
        out.write(QJsonDocument(QJsonObject{{QStringLiteral("machine"), name},
                                            {QStringLiteral("devices"), entries}})
                      .toJson()) <= 0)
        qFatal("cannot write %s", qPrintable(file));
    out.close();
    QProcess cli;
    cli.setProgram(QStringLiteral(CAMBENCH_CLI_EXE));
    cli.setArguments(QStringList{QStringLiteral("machine"), QStringLiteral("backup"), file} +
                     (into.isEmpty() ? QStringList{QStringLiteral("-o"),
                                                   dir.filePath(name + QStringLiteral("-backup"))}
                                     : into));
    e2e::endWithThisTest(cli);
    QElapsedTimer timer;
    timer.start();
    cli.start();
    if (!cli.waitForFinished(-1) || cli.exitStatus() != QProcess::NormalExit || cli.exitCode() != 0)
        qFatal("machine backup of %s failed: %s%s", qPrintable(name),
               cli.readAllStandardOutput().constData(), cli.readAllStandardError().constData());
    return timer.nsecsElapsed() / 1e9;
}

double median(QList<double> values) {
    std::sort(values.begin(), values.end());
    return values.at(values.size() / 2);
}

}  // namespace

void benchMachine(int baud, int repeat) {
    QTextStream out(stdout);
    QTemporaryDir dir;
    QList<Device> all = devices(baud);
    std::vector<std::unique_ptr<QProcess>> sims;
    for (Device& device : all) {
        sims.push_back(std::make_unique<QProcess>());
        device.entry.insert(
            QStringLiteral("port"),
            startSim(*sims.back(), QStringList{QStringLiteral("--baud"), QString::number(baud)} +
                                       device.simArgs));
    }
    out << QStringLiteral("median of %1 run(s) each, %2 baud, throttled simulators on ptys\n\n")
               .arg(repeat)
               .arg(baud)
        << "| backup | devices | time |\n| --- | ---: | ---: |\n";
    out.flush();
    double slowest = 0;
    double sum = 0;  // what the machine took before, one device after the other
    QJsonArray machine;
    for (const Device& device : all) {
        QList<double> times;
        for (int i = 0; i < repeat; ++i)
            times << timeBackup(dir, device.name, QJsonArray{device.entry});
        const double alone = median(times);
        slowest = std::max(slowest, alone);
        sum += alone;
        machine << device.entry;
        out << QStringLiteral("| %1 (%2) alone | 1 | %3 s |\n")
                   .arg(device.name, device.family)
                   .arg(alone, 0, 'f', 2);
        out.flush();
    }
    QList<double> times;
    for (int i = 0; i < repeat; ++i) times << timeBackup(dir, QStringLiteral("machine"), machine);
    const double together = median(times);
    out << QStringLiteral("| the machine, 3 ports at once | 3 | %1 s |\n").arg(together, 0, 'f', 2);
    out.flush();
    // Into an archive (issue 37): a new one each run (the first version:
    // git init, the commit), then one archive again and again (nothing
    // changed: the latest version taken out and compared, no commit).
    QList<double> first;
    QList<double> again;
    for (int i = 0; i < repeat; ++i) {
        first << timeBackup(
            dir, QStringLiteral("machine"), machine,
            {QStringLiteral("--archive"), dir.filePath(QStringLiteral("archive-%1").arg(i)),
             QStringLiteral("-m"), QStringLiteral("bench")});
        again << timeBackup(dir, QStringLiteral("machine"), machine,
                            {QStringLiteral("--archive"), dir.filePath(QStringLiteral("archive-0")),
                             QStringLiteral("-m"), QStringLiteral("bench")});
    }
    const double archived = median(first);
    const double compared = median(again);
    out << QStringLiteral("| the machine into a new archive (first version) | 3 | %1 s |\n")
               .arg(archived, 0, 'f', 2)
        << QStringLiteral("| the machine into its archive, nothing changed | 3 | %1 s |\n\n")
               .arg(compared, 0, 'f', 2)
        << QStringLiteral(
               "into the archive / slowest alone: %1 (first version), %2 (nothing "
               "changed); target <= 1.2\n")
               .arg(archived / slowest, 0, 'f', 2)
               .arg(compared / slowest, 0, 'f', 2)
        << QStringLiteral(
               "machine / slowest alone: %1 (target <= 1.2); the devices one after "
               "the other would take their sum, %2 s\n")
               .arg(together / slowest, 0, 'f', 2)
               .arg(sum, 0, 'f', 2);
    for (const std::unique_ptr<QProcess>& sim : sims) {
        sim->kill();
        sim->waitForFinished(5000);
    }
}

}  // namespace cambench::bench
