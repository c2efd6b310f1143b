// Issue 35, item 1 for the MC-1: after STOP nothing moves until the person
// asks again. A STOP lands after each request of each motion job (an axis
// command with the axes not known yet - its identification and RDTABLE
// probes first -, a move, a jog, homing, a program start, a restore
// midway), through the real worker on the in-process simulated MC200 V2;
// no telegram that moves or writes follows it, the job says "stopped
// before it moved" and nothing more of it is sent. What moves is told from
// the telegrams' bytes by hand (manual chapter 3), not by the code under
// test.
#include "../worker/stop_at_request.h"

#include "comm/mc1/mc1_device.h"
#include "comm/mc1/mc1_protocol.h"
#include "comm/mc1/usecases/mc1_backup_restore.h"

#include <QtTest>

using namespace cambench;
using namespace cambench::comm;
using namespace cambench::comm::test;

namespace {

constexpr int kWaitMs = 60000;  // bounds a hang; never a speed check

// Whether a telegram moves an axis, starts or steps the program or writes
// (manual tables 41-45, 3.x): AXIS_DATA 9F; AXIS_NODATA 9B but its stops 08
// and 09; SYSDATA 92 start 01 and step 03; 93 reset 05 and flash 0A; the
// writes WRVAR CE/CF, WRBYTE 2B/AC, WRBIT 3B/BB, WRSTAT EF, WRMEM DE.
bool movesOrWrites(const QByteArray& telegram) {
    if (telegram.size() < 3) return false;
    const quint8 op = quint8(telegram.at(0));
    switch (op) {
        case 0x9F:
        case 0xCE:
        case 0xCF:
        case 0x2B:
        case 0xAC:
        case 0x3B:
        case 0xBB:
        case 0xEF:
        case 0xDE:
            return true;
        case 0x9B:
            return telegram.size() > 3 && quint8(telegram.at(3)) != 0x08 &&
                   quint8(telegram.at(3)) != 0x09;
        case 0x92:
            return quint8(telegram.at(2)) == 0x01 || quint8(telegram.at(2)) == 0x03;
        case 0x93:
            return quint8(telegram.at(2)) == 0x05 || quint8(telegram.at(2)) == 0x0A;
        default:
            return false;
    }
}

// A worker connected to a fresh simulated MC200 V2 with axes 1, 2 and 5.
std::unique_ptr<JobRunner> connectedWorker() {
    std::unique_ptr<JobRunner> worker = makeCommWorker();
    auto settings = std::make_shared<Mc1ProtocolSettings>();
    worker->connectTo(
        ConnectionSettings{QStringLiteral("sim:variant=mc200v2;axes=1,2,5"), SerialSettings{}, {}},
        settings);
    (void)QTest::qWaitFor([&worker] { return worker->state() == ConnectionState::Connected; },
                          kWaitMs);
    return worker;
}

template <class T>
Result<T> runOn(JobRunner& worker, std::function<Result<T>(Mc1Device&)> work) {
    std::optional<Result<T>> result;
    QObject context;
    worker.run<Result<T>>(
        &context, JobPriority::User, QStringLiteral("setup"),
        [work](JobContext& job) -> Result<T> {
            Result<Mc1Device*> device = job.family<Mc1Device>();
            if (!device) return device.error();
            return work(**device);
        },
        [&result](Result<T> r) { result = std::move(r); });
    (void)QTest::qWaitFor([&result] { return result.has_value(); }, kWaitMs);
    return result ? *result : Error::communication(QStringLiteral("no answer"));
}

Result<QString> axisOutcome(const Result<Mc1AxisDone>& done) {
    if (!done) return done.error();
    return QStringLiteral("done");
}

// `work` on the MC-1 of a job.
std::function<Result<QString>(JobContext&)> onMc1(std::function<Result<QString>(Mc1Device&)> work) {
    return [work](JobContext& job) -> Result<QString> {
        Result<Mc1Device*> device = job.family<Mc1Device>();
        if (!device) return device.error();
        return work(**device);
    };
}

// A fresh controller; `setup` run on it first (none: nothing).
std::function<std::unique_ptr<JobRunner>()> fresh(std::function<Status(Mc1Device&)> setup = {}) {
    return [setup]() -> std::unique_ptr<JobRunner> {
        std::unique_ptr<JobRunner> worker = connectedWorker();
        if (!setup) return worker;
        const Result<bool> done = runOn<bool>(*worker, [setup](Mc1Device& d) -> Result<bool> {
            if (const Status ok = setup(d); !ok) return ok.error();
            return true;
        });
        if (!done) return nullptr;
        return worker;
    };
}

QList<MotionJobUnderTest> motionJobs() {
    const auto knowAxes = [](Mc1Device& device) -> Status {
        const Result<Mc1Axes> axes = device.axes();
        return axes ? success() : Status(axes.error());
    };
    const auto axis = [](Mc1AxisCommand command, qint32 value) {
        return onMc1([command, value](Mc1Device& device) {
            return axisOutcome(device.axisCommand(2, command, value));
        });
    };
    // Five variables differ from the backup: the restore writes five items.
    const auto changeVariables = [](Mc1Device& device) -> Status {
        for (int v = 1; v <= 5; ++v)
            if (const Status ok = device.writeVariable(v, 100 + v); !ok) return ok;
        return success();
    };
    return {
        {QStringLiteral("move, axes not known"), fresh(), axis(Mc1AxisCommand::MoveAbsolute, 1000),
         movesOrWrites},
        {QStringLiteral("move"), fresh(knowAxes), axis(Mc1AxisCommand::MoveAbsolute, 1000),
         movesOrWrites},
        {QStringLiteral("jog"), fresh(knowAxes), axis(Mc1AxisCommand::JogPlus, 0), movesOrWrites},
        {QStringLiteral("homing"), fresh(knowAxes), axis(Mc1AxisCommand::Home, 0), movesOrWrites},
        {QStringLiteral("program start"), fresh(knowAxes),
         onMc1([](Mc1Device& device) -> Result<QString> {
             const Result<Mc1Done<Mc1ProgramStatus>> done =
                 device.programCommand(Mc1ProgramCommand::Start);
             if (!done) return done.error();
             return QStringLiteral("done");
         }),
         movesOrWrites},
        {QStringLiteral("restore"), fresh(changeVariables),
         onMc1([](Mc1Device& device) -> Result<QString> {
             Mc1Backup backup;
             backup.variant = QStringLiteral("mc200v2");
             for (int v = 1; v <= 5; ++v) backup.variables.insert(v, -v);
             // Built here, it records no identity: confirmed as a person
             // confirms an older backup.
             const Result<usecases::OutcomeTally> tally =
                 usecases::restoreMc1Backup(device, backup, ReplacementConsent::any());
             if (!tally) return tally.error();
             QStringList lines;
             for (const usecases::OutcomeLine& line : tally->lines()) lines << line.text;
             return lines.join(QLatin1Char('\n'));
         }),
         movesOrWrites},
    };
}

}  // namespace

class TestMc1StopGeneration : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aStopInsideEveryStepOfEveryMotionJobLetsNothingMoveAfterIt_data() {
        motionJobRows(motionJobs());
    }
    void aStopInsideEveryStepOfEveryMotionJobLetsNothingMoveAfterIt() {
        QFETCH(int, job);
        stopInsideEveryStep(motionJobs().at(job));
    }

    void aJobAskedAfterTheStopMovesAgain() {
        // The STOP holds back what was asked before it, not what comes after.
        std::unique_ptr<JobRunner> worker = connectedWorker();
        const StopRun<QString> stopped =
            runWithStopAfter<QString>(*worker, 0, [](JobContext& ctx) -> Result<QString> {
                Result<Mc1Device*> device = ctx.family<Mc1Device>();
                if (!device) return device.error();
                return axisOutcome((*device)->axisCommand(1, Mc1AxisCommand::JogPlus, 0));
            });
        QVERIFY(stopped.result && !stopped.result->ok());
        QCOMPARE(stopped.result->error().kind, ErrorKind::Cancelled);
        const Result<Mc1AxisDone> again = runOn<Mc1AxisDone>(
            *worker, [](Mc1Device& d) { return d.axisCommand(1, Mc1AxisCommand::JogPlus, 0); });
        QVERIFY2(again.ok(), qPrintable(again.error().message));
        QVERIFY(again->after && again->after->moving);
    }
};

QTEST_GUILESS_MAIN(TestMc1StopGeneration)
#include "tst_mc1_stop_generation.moc"
