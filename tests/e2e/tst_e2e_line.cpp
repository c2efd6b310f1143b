// backup-line and verify-line: the real cambench-cli against the real
// cambench-sim with three devices on one Multiuser line.
#include "e2e_support.h"

#include <QCryptographicHash>
#include <QDeadlineTimer>
#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>
#include <QThread>

using namespace cambench::e2e;

namespace {

const QStringList kLineOfThree{"--verbose", "--protocol", "multiuser", "--devices", "1,2,3"};

QJsonArray manifestDevices(const QString& dir) {
    return QJsonDocument::fromJson(readBytes(QDir(dir).filePath(QStringLiteral("manifest.json"))))
        .object()
        .value(QStringLiteral("devices"))
        .toArray();
}

QString sha256Of(const QString& path) {
    return QString::fromLatin1(
        QCryptographicHash::hash(readBytes(path), QCryptographicHash::Sha256).toHex());
}

// The simulator's log lines (cambench-sim --verbose) from byte `from` on.
QStringList simLog(const SimSession& session, qsizetype from = 0) {
    return QString::fromUtf8(readBytes(session.path(QStringLiteral("sim-stderr.log"))).mid(from))
        .split(u'\n', Qt::SkipEmptyParts);
}

}  // namespace

class TestE2eLine : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void backupLineGoesOnPastADeadDevice();
    void scanFindsOnlyTheDevicesThatAnswer();
    void resumeAfterACutRunSkipsSavedDevices();
    void backupLineNeedsMultiuser();
};

void TestE2eLine::backupLineGoesOnPastADeadDevice() {
    SimSession session;
    START_SIM(session, kLineOfThree + QStringList{"--dead-devices", "2"});
    const QString dir = session.path(QStringLiteral("line"));
    const CliRun run =
        session.cliMultiuser({"--timeout", "200", "backup-line", "-o", dir, "--devices", "1,2,3"});
    VERIFY_EXIT(run, 3);
    QVERIFY2(run.out.contains(QLatin1String("device 1: saved device-01_11.10.1994_32out.json\n")),
             qPrintable(run.out));
    QVERIFY(run.out.contains(QLatin1String("device 2: FAILED: ")));
    QVERIFY(run.out.contains(QLatin1String("device 3: saved device-03_11.10.1994_32out.json\n")));
    QVERIFY(run.out.contains(QLatin1String("3 devices: 2 saved, 1 failed")));
    QVERIFY(run.err.contains(QLatin1String("--resume")));

    const QJsonArray devices = manifestDevices(dir);
    QCOMPARE(devices.size(), 3);
    for (const QJsonValue& value : devices) {
        const QJsonObject entry = value.toObject();
        const int device = entry.value(QStringLiteral("device")).toInt();
        QVERIFY(QDateTime::fromString(entry.value(QStringLiteral("time")).toString(), Qt::ISODate)
                    .isValid());
        if (device == 2) {
            QCOMPARE(entry.value(QStringLiteral("result")).toString(), QStringLiteral("failed"));
            QVERIFY(!entry.value(QStringLiteral("message")).toString().isEmpty());
            QCOMPARE(entry.value(QStringLiteral("file")).toString(), QString());
            continue;
        }
        QCOMPARE(entry.value(QStringLiteral("result")).toString(), QStringLiteral("saved"));
        QCOMPARE(entry.value(QStringLiteral("identity"))
                     .toObject()
                     .value(QStringLiteral("deviceNumber"))
                     .toInt(),
                 device);
        const QString file = QDir(dir).filePath(entry.value(QStringLiteral("file")).toString());
        QCOMPARE(entry.value(QStringLiteral("sha256")).toString(), sha256Of(file));
        // The image verifies against its device with the plain verify command.
        VERIFY_EXIT(session.cliMultiuser({"--device", QString::number(device), "verify", file}), 0);
    }

    const CliRun verify = session.cliMultiuser({"--timeout", "200", "verify-line", dir});
    VERIFY_EXIT(verify, 1);  // device 2 has no image to compare
    QVERIFY2(verify.out.contains(QLatin1String("device 1: the device equals device-01_")),
             qPrintable(verify.out));
    QVERIFY(verify.out.contains(QLatin1String("device 3: the device equals device-03_")));
    QVERIFY(verify.out.contains(QLatin1String("device 2: not verified")));
}

void TestE2eLine::scanFindsOnlyTheDevicesThatAnswer() {
    SimSession session;
    START_SIM(session, kLineOfThree + QStringList{"--dead-devices", "2"});
    const QString dir = session.path(QStringLiteral("line"));
    const CliRun run = session.cliMultiuser({"--timeout", "100", "backup-line", "-o", dir});
    VERIFY_EXIT(run, 0);
    QCOMPARE(manifestDevices(dir).size(), 2);
    const CliRun verify = session.cliMultiuser({"verify-line", dir});
    VERIFY_EXIT(verify, 0);
}

void TestE2eLine::resumeAfterACutRunSkipsSavedDevices() {
    SimSession session;
    // Slow replies, so that the run can be cut after the first device.
    START_SIM(session, kLineOfThree + QStringList{"--delay", "40"});
    const QString dir = session.path(QStringLiteral("line"));
    const QStringList args{"--timeout", "3000", "backup-line", "-o", dir, "--devices", "1,2,3"};

    QProcess cut;
    cut.setProgram(QStringLiteral(CAMBENCH_CLI_EXE));
    cut.setArguments(
        QStringList{"--port", session.ptyPath(), "--baud", kFastBaud, "--protocol", "multiuser"} +
        args);
    endWithThisTest(cut);
    cut.start();
    QVERIFY(cut.waitForStarted(hangBoundMs(10000)));
    // Bounded wait for the manifest to name the first device as saved.
    const QDeadlineTimer deadline(hangBoundMs(60000));
    while (manifestDevices(dir).isEmpty() && !deadline.hasExpired() &&
           cut.state() == QProcess::Running)
        QThread::msleep(20);
    cut.kill();
    cut.waitForFinished(5000);
    const QJsonArray before = manifestDevices(dir);
    QVERIFY2(before.size() == 1, "the run was not cut after the first device");
    QCOMPARE(before.at(0).toObject().value(QStringLiteral("device")).toInt(), 1);

    const qsizetype logBefore = readBytes(session.path(QStringLiteral("sim-stderr.log"))).size();
    const CliRun resumed = session.cliMultiuser(args + QStringList{"--resume"});
    VERIFY_EXIT(resumed, 0);
    QVERIFY2(resumed.out.contains(QLatin1String("device 1: saved device-01_11.10.1994_32out.json "
                                                "(by an earlier run, file checked)")),
             qPrintable(resumed.out));
    QVERIFY(resumed.out.contains(QLatin1String("3 devices: 3 saved, 0 failed")));
    // Device 1 was not read again.
    for (const QString& line : simLog(session, logBefore))
        QVERIFY2(!line.contains(QLatin1String("device 1 <-")), qPrintable(line));
    QCOMPARE(manifestDevices(dir).size(), 3);
    VERIFY_EXIT(session.cliMultiuser({"--timeout", "3000", "verify-line", dir}), 0);
}

// A line command speaks Multiuser unless told otherwise (issue 39); told a
// point-to-point protocol, it says which it needs, and nothing is sent.
void TestE2eLine::backupLineNeedsMultiuser() {
    SimSession session;
    START_SIM(session);
    const CliRun run = session.cli(
        {"--protocol", "standard", "backup-line", "-o", session.path(QStringLiteral("x"))});
    VERIFY_EXIT(run, 1);
    QVERIFY2(run.err.contains(QLatin1String("speaks Multiuser")), qPrintable(run.err));
}

QTEST_GUILESS_MAIN(TestE2eLine)
#include "tst_e2e_line.moc"
