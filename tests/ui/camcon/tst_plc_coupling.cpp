// Issue 12, point 5: the PLC coupling page on the table interface sends the
// short commands 0x01..0x07 as the S7's function block does, shows the
// answers as the data block holds them, asks before every write and reports
// what the device holds afterwards. The GUI on the real QSerialPort against
// a simulated CamCon speaking 3964R on a pseudo-terminal; the simulator's
// state is the witness.
#include "camcon_fixture.h"

#include "comm/sim/camcon/sim_demo.h"
#include "comm/sim/camcon/sim_device.h"
#include "comm/sim/sim_pacer.h"
#include "comm/sim/sim_pty_server.h"
#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/plc_coupling_page.h"
#include "ui/language.h"

#include <QAbstractButton>
#include <QDoubleSpinBox>
#include <QMessageBox>
#include <QSpinBox>
#include <QTableWidget>
#include <QtTest>

using namespace cambench;
using namespace cambench::test;

namespace {

// A CamCon speaking 3964R n96 on a pseudo-terminal in the test process.
struct TableSimulator {
    TableSimulator() {
        comm::SimPortConfig config;
        config.throttle = false;
        config.tableVariant = comm::table::Rk512Variant::N96;
        endpoint = comm::makeSimEndpoint(config);
        pacer = std::make_unique<comm::SimPacer>(config.baud, false);
        server = std::make_unique<comm::SimPtyServer>(*endpoint, *pacer);
        open = server->open().ok();
    }
    comm::SimDevice& device() { return *endpoint->device(0); }

    std::unique_ptr<comm::SimCamConEndpoint> endpoint;
    std::unique_ptr<comm::SimPacer> pacer;
    std::unique_ptr<comm::SimPtyServer> server;
    bool open = false;
};

// Answers the next question box with `button`.
std::unique_ptr<NextDialog<QMessageBox>> answerQuestion(QMessageBox::StandardButton button) {
    return std::make_unique<NextDialog<QMessageBox>>(
        [button](QMessageBox* box) { box->button(button)->click(); });
}

}  // namespace

class PlcCouplingTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() {
        useTestSettings();
        QVERIFY(setLanguage(QStringLiteral("en")));
    }
    void statusIsShownAsTheDataBlockHoldsIt();
    void deadTimeIsWrittenOnlyAfterYes();
    void camsWrittenReachTheDevice();
    void programChangeIsConfirmedByTheDevice();
};

namespace {

struct Bench {
    TableSimulator sim;
    std::unique_ptr<Shell> shell;
    PlcCouplingPage* page = nullptr;

    bool start() {
        if (!sim.open) return false;
        shell = startOnSimulator(sim.server->slavePath(), QStringLiteral("3964r-n96"));
        if (!shell) return false;
        page = shell->window()->findChild<PlcCouplingPage*>();
        return page && gateOf(shell->window(), page)->isAvailable();
    }
    bool waitForOutcome(const QString& before) {
        return QTest::qWaitFor([this, before] { return page->lastOutcome() != before; },
                               kDeviceTimeoutMs);
    }
};

}  // namespace

void PlcCouplingTest::statusIsShownAsTheDataBlockHoldsIt() {
    Bench bench;
    QVERIFY(bench.start());
    bench.page->readStatus();
    QTRY_VERIFY_WITH_TIMEOUT(!bench.page->statusInWords().isEmpty(), kDeviceTimeoutMs);
    QVERIFY2(bench.page->statusInWords().contains(QLatin1String("program 0 active")),
             qPrintable(bench.page->statusInWords()));
    QVERIFY(bench.page->statusInWords().contains(QLatin1String("device status OK")));
}

void PlcCouplingTest::deadTimeIsWrittenOnlyAfterYes() {
    Bench bench;
    QVERIFY(bench.start());
    bench.page->outputBox()->setValue(5);
    bench.page->deadTimeBox()->setValue(12.5);
    {
        const auto no = answerQuestion(QMessageBox::No);
        bench.page->writeDeadTime();
        QCOMPARE(no->answered(), 1);
    }
    QVERIFY(!bench.sim.device().state().deadTimes.contains(4) ||
            bench.sim.device().state().deadTimes.value(4) != 125);
    QVERIFY(bench.page->lastOutcome().isEmpty());

    const auto yes = answerQuestion(QMessageBox::Yes);
    bench.page->writeDeadTime();
    QVERIFY(bench.waitForOutcome(QString()));
    QVERIFY2(bench.page->lastOutcome().contains(QLatin1String("dead time of output 5 (0x07): "
                                                              "written")),
             qPrintable(bench.page->lastOutcome()));
    QCOMPARE(bench.sim.device().state().deadTimes.value(4), 125);
    // Read back after the write: the page and the Dead times section's
    // device copy show what the device holds, not the value before.
    QTRY_COMPARE_WITH_TIMEOUT(camConWorkspace(*bench.shell)->cams()->deviceDeadTime(5).value_or(-1),
                              125, kDeviceTimeoutMs);
    QCOMPARE(bench.page->deadTimeBox()->value(), 12.5);
}

void PlcCouplingTest::camsWrittenReachTheDevice() {
    Bench bench;
    QVERIFY(bench.start());
    bench.page->programBox()->setValue(1);
    bench.page->outputBox()->setValue(5);
    bench.page->readTrack();
    QVERIFY(bench.waitForOutcome(QString()));
    QTableWidget* table = bench.page->camTable();
    table->setRowCount(2);
    const QList<Cam> wanted{{10, 20}, {100, 120}};
    for (int row = 0; row < 2; ++row) {
        auto* on = new QTableWidgetItem;
        on->setData(Qt::EditRole, wanted.at(row).on);
        auto* off = new QTableWidgetItem;
        off->setData(Qt::EditRole, wanted.at(row).off);
        table->setItem(row, 0, on);
        table->setItem(row, 1, off);
    }
    const QString before = bench.page->lastOutcome();
    const auto yes = answerQuestion(QMessageBox::Yes);
    bench.page->writeTrack();
    QVERIFY(bench.waitForOutcome(before));
    QVERIFY2(bench.page->lastOutcome().contains(QLatin1String("written")),
             qPrintable(bench.page->lastOutcome()));
    QCOMPARE(bench.sim.device().state().cams.track(1, 4), wanted);
}

void PlcCouplingTest::programChangeIsConfirmedByTheDevice() {
    Bench bench;
    QVERIFY(bench.start());
    const auto yes = answerQuestion(QMessageBox::Yes);
    bench.page->changeProgram(2);
    QVERIFY(bench.waitForOutcome(QString()));
    QVERIFY2(bench.page->lastOutcome().contains(QLatin1String("active program (0x03): written")),
             qPrintable(bench.page->lastOutcome()));
    bench.page->readStatus();
    QTRY_VERIFY_WITH_TIMEOUT(bench.page->statusInWords().contains(QLatin1String("program 2")),
                             kDeviceTimeoutMs);
}

QTEST_MAIN(PlcCouplingTest)
#include "tst_plc_coupling.moc"
