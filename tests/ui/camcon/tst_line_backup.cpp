// Issue 9: Device → Back up all devices on this line, one progress bar per
// device, going on past a device that does not answer and saying so.
#include "camcon_fixture.h"

#include "comm/camcon/ascii/ascii_protocol.h"
#include "model/camcon/line_manifest.h"
#include "ui/camcon/line_backup_dialog.h"
#include "ui/device_session.h"
#include "ui/language.h"

#include <QDir>
#include <QProgressBar>
#include <QTemporaryDir>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

class LineBackupTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        useTestSettings();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void everyDeviceGetsItsBarAndAFailureIsSaid();
};

void LineBackupTest::everyDeviceGetsItsBarAndAFailureIsSaid() {
    auto shell = std::make_unique<Shell>();
    shell->start({});
    comm::ConnectionSettings line;
    line.port = QStringLiteral("sim:throttle=0;devices=0,5,7;framing=multiuser");
    line.protocol = QStringLiteral("multiuser");
    comm::AsciiProtocolSettings multiuser(comm::Framing::Multiuser);
    multiuser.ascii.timeoutMs = 100;  // device 9 is absent: a short wait per attempt
    shell->session()->connectTo(line, std::make_shared<comm::AsciiProtocolSettings>(multiuser));
    QTRY_VERIFY_WITH_TIMEOUT(shell->session()->isOnline(), kDeviceTimeoutMs);

    QTemporaryDir dir;
    LineBackupDialog* dialog = camConWindow(shell->window())->openLineBackup();
    dialog->setDirectory(dir.path());
    dialog->setDevices(QStringLiteral("0, 5, 9"));
    QSignalSpy finished(dialog, &LineBackupDialog::finished);
    dialog->start();
    QVERIFY(finished.wait(kDeviceTimeoutMs));
    QCOMPARE(finished.first().first().toBool(), false);  // not every device was saved
    QCOMPARE(dialog->deviceBarCount(), 3);
    QCOMPARE(dialog->deviceBar(0)->value(), dialog->deviceBar(0)->maximum());
    QCOMPARE(dialog->deviceBar(5)->value(), dialog->deviceBar(5)->maximum());
    QCOMPARE(dialog->deviceBar(9)->format(), QStringLiteral("FAILED"));
    // Red, and full: it stands out beside the saved ones (issue 12, point 8).
    QVERIFY(dialog->deviceBar(9)->styleSheet().contains(QLatin1String("#b03a2e")));
    QCOMPARE(dialog->deviceBar(9)->value(), dialog->deviceBar(9)->maximum());
    QVERIFY(dialog->deviceBar(0)->styleSheet().isEmpty());
    const QString report = dialog->reportText();
    QVERIFY2(report.startsWith(QStringLiteral("2 of 3 devices saved")), qPrintable(report));
    QVERIFY(report.contains(QStringLiteral("Device 9: NOT saved")));
    const Result<LineManifest> manifest =
        loadLineManifest(QDir(dir.path()).filePath(QLatin1String(kLineManifestName)));
    QVERIFY(manifest.ok());
    QCOMPARE(manifest->devices.size(), 3);
    // The line is addressed to the device the window works with again.
    QCOMPARE(shell->session()->protocol().device(), 0);
    dialog->close();
}

QTEST_MAIN(LineBackupTest)
#include "tst_line_backup.moc"
