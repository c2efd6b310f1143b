// `cambench-cli detect` against the real cambench-sim on a pseudo-terminal
// (issue 13, point 3): each family's protocols are tried at their default
// line settings until one identifies the device; a silent line names
// everything tried. And the family-neutral command front: a family's
// commands are its own group.
#include "../e2e_support.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>

using namespace cambench::e2e;

class TestE2eDetect : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void findsTheTableInterface() {
        SimSession session;
        START_SIM(session, {"--protocol", "3964r-n96"});
        const CliRun run = runCli({"--port", session.ptyPath(), "detect"});
        VERIFY_EXIT(run, 0);
        QVERIFY2(run.out.startsWith(QLatin1String("camcon: CamCon, EPROM")), describe(run));
        QVERIFY2(run.out.contains(QLatin1String("(3964r-n96, 9600 baud 8N1)")), describe(run));

        const CliRun json = runCli({"--port", session.ptyPath(), "detect", "--json"});
        VERIFY_EXIT(json, 0);
        const QJsonObject root = QJsonDocument::fromJson(json.out.toUtf8()).object();
        QCOMPARE(root.value(QStringLiteral("found")).toObject().value(QStringLiteral("protocol")),
                 QJsonValue(QStringLiteral("3964r-n96")));
        // Cam-BUS (listening only), Standard and Multiuser were tried first
        // and did not answer.
        const QJsonArray attempts = root.value(QStringLiteral("attempts")).toArray();
        QCOMPARE(attempts.size(), 4);
        QCOMPARE(attempts.at(0).toObject().value(QStringLiteral("protocol")),
                 QJsonValue(QStringLiteral("cambus")));
        QVERIFY(attempts.at(0).toObject().contains(QStringLiteral("failure")));
    }

    // A Cam-BUS is found by listening: no byte is sent to it. The simulated
    // bus forms by itself (silence, then an initialisation phase): Detect
    // started at once waits that out.
    void findsACamBusByListening() {
        SimSession session(QStringLiteral("cambus"));
        START_SIM(session, {"--devices", "3,7", "--display", "12"});
        const CliRun run = runCli({"--port", session.ptyPath(), "detect"});
        VERIFY_EXIT(run, 0);
        QVERIFY2(run.out.startsWith(QLatin1String("camcon: a Cam-BUS: users 3, 7, 12 get the "
                                                  "token")),
                 describe(run));
        QVERIFY2(run.out.contains(QLatin1String("(cambus, 38400 baud 8N1)")), describe(run));
    }

    // Issue 39, item 3: the built-in simulated port is one device, as its
    // name says - a Standard CamCon for "sim" - not whatever each probe
    // speaks (it said "a Cam-BUS: users 0 get the token").
    void namesWhatTheSimulatedPortIs() {
        const CliRun plain = runCli({"detect", "--json"});
        VERIFY_EXIT(plain, 0);
        const QJsonObject found = QJsonDocument::fromJson(plain.out.toUtf8())
                                      .object()
                                      .value(QStringLiteral("found"))
                                      .toObject();
        QCOMPARE(found.value(QStringLiteral("protocol")), QJsonValue(QStringLiteral("standard")));
        QVERIFY2(found.value(QStringLiteral("found"))
                     .toString()
                     .startsWith(QLatin1String("CamCon, EPROM")),
                 describe(plain));
        const CliRun table = runCli({"--port", "sim:protocol=3964r-n96", "detect"});
        VERIFY_EXIT(table, 0);
        QVERIFY2(table.out.contains(QLatin1String("(3964r-n96, 9600 baud 8N1)")), describe(table));
        // A port with another family's keys is that family's device.
        const CliRun mc = runCli({"--port", "sim:variant=mc200v1", "detect"});
        VERIFY_EXIT(mc, 0);
        QVERIFY2(mc.out.startsWith(QLatin1String("mc1: MC200 V1 (probed)")), describe(mc));
    }

    void findsAMultiuserDeviceAtTheNumberGiven() {
        SimSession session;
        START_SIM(session, {"--protocol", "multiuser", "--devices", "7"});
        const CliRun run = runCli({"--port", session.ptyPath(), "--device", "7", "detect"});
        VERIFY_EXIT(run, 0);
        QVERIFY2(run.out.contains(QLatin1String("device 7")), describe(run));
        QVERIFY2(run.out.contains(QLatin1String("(multiuser, 38400 baud 8N1)")), describe(run));
    }

    void silentLineNamesEveryTry() {
        SimSession session;
        START_SIM(session, {"--dead"});
        const CliRun run = runCli({"--port", session.ptyPath(), "detect"});
        VERIFY_EXIT(run, 3);
        QVERIFY2(run.err.contains(QLatin1String("nothing answered on ") + session.ptyPath()),
                 describe(run));
        for (const char* protocol : {"standard", "multiuser", "3964r-n96", "3964r-e38"})
            QVERIFY2(run.err.contains(QLatin1String(protocol)), describe(run));
        QVERIFY(run.out.isEmpty());
    }

    void missingPortIsSaidAtOnce() {
        const CliRun run = runCli({"--port", "/dev/cambench-no-such-port", "detect"});
        VERIFY_EXIT(run, 3);
        QVERIFY2(run.err.contains(QLatin1String("/dev/cambench-no-such-port")), describe(run));
    }

    // The shell's commands work for any family; a family's own are its group.
    void commandsBelongToTheirFamily() {
        const CliRun help = runCli({"--help"});
        VERIFY_EXIT(help, 0);
        QVERIFY(help.out.contains(QLatin1String("Commands for every family:")));
        QVERIFY(help.out.contains(QLatin1String("Digitronic CamCon (--family camcon):")));
        const CliRun unknown = runCli({"frobnicate"});
        VERIFY_EXIT(unknown, 2);
        QVERIFY2(unknown.err.contains(QLatin1String("unknown command \"frobnicate\"")),
                 describe(unknown));
    }
};

QTEST_MAIN(TestE2eDetect)
#include "tst_e2e_detect.moc"
