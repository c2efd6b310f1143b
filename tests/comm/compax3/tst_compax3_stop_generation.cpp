// Issue 35, item 1 for the Compax3: after STOP nothing moves until the
// person asks again. A STOP lands after each request of each motion job (a
// set start: its status read, each set object's read and write, the select
// and the start; enable; jog), through the real worker on the in-process
// simulated drive; no write of the job follows it (every write to a
// Compax3 can move its axis or change its power), the job says "stopped
// before it moved" and nothing more of it is sent.
#include "../worker/stop_at_request.h"

#include "comm/compax3/compax3_device.h"
#include "comm/compax3/compax3_protocol.h"

#include <QtTest>

using namespace cambench;
using namespace cambench::comm;
using namespace cambench::comm::test;

namespace {

constexpr int kWaitMs = 60000;  // bounds a hang; never a speed check

// A write "Onnnn.s=value" (the manual's object syntax); reads and "_?"
// have no '='.
bool writes(const QByteArray& command) {
    return command.contains('=');
}

Result<QString> outcome(const Result<Compax3CommandResult>& done) {
    if (!done) return done.error();
    return done->summary();
}

// `work` on the Compax3 of a job.
std::function<Result<QString>(JobContext&)> onDrive(
    std::function<Result<Compax3CommandResult>(Compax3Device&)> work) {
    return [work](JobContext& job) -> Result<QString> {
        Result<Compax3Device*> device = job.family<Compax3Device>();
        if (!device) return device.error();
        return outcome(work(**device));
    };
}

// A worker on a fresh simulated drive (powerless), powered first when
// `powered`.
std::function<std::unique_ptr<JobRunner>()> fresh(bool powered) {
    return [powered]() -> std::unique_ptr<JobRunner> {
        std::unique_ptr<JobRunner> worker = makeCommWorker();
        worker->connectTo(ConnectionSettings{QStringLiteral("sim"), SerialSettings{}, {}},
                          std::make_shared<Compax3ProtocolSettings>(false));
        if (!QTest::qWaitFor([&worker] { return worker->state() == ConnectionState::Connected; },
                             kWaitMs))
            return nullptr;
        if (!powered) return worker;
        std::optional<Result<QString>> enabled;
        QObject context;
        worker->run<Result<QString>>(
            &context, JobPriority::User, QStringLiteral("enable"),
            onDrive([](Compax3Device& d) { return d.motion(Compax3Motion::Enable); }),
            [&enabled](Result<QString> r) { enabled = std::move(r); });
        (void)QTest::qWaitFor([&enabled] { return enabled.has_value(); }, kWaitMs);
        if (!enabled || !enabled->ok()) return nullptr;
        return worker;
    };
}

QList<MotionJobUnderTest> motionJobs() {
    Compax3SetMove move;
    move.set = 1;
    move.target = 4321;
    move.velocity = 77;
    move.acceleration = 333;
    return {
        {QStringLiteral("set start"), fresh(true),
         onDrive([move](Compax3Device& d) { return d.moveSet(move); }), writes},
        {QStringLiteral("enable"), fresh(false),
         onDrive([](Compax3Device& d) { return d.motion(Compax3Motion::Enable); }), writes},
        {QStringLiteral("jog"), fresh(true),
         onDrive([](Compax3Device& d) { return d.motion(Compax3Motion::JogPlus); }), writes},
    };
}

// Whether a STOP powers a powerless drive (the defect of issue 35 item 2:
// 1100.3 = $0001 is a rising edge of bit 0). Then the STOP, not the job,
// powers it, and an enable the STOP overtakes finds it powered already.
bool stopPowersAPowerlessDrive() {
    std::unique_ptr<JobRunner> worker = fresh(false)();
    if (!worker) return false;
    std::optional<Result<QString>> after;
    QObject context;
    worker->run<Result<QString>>(
        &context, JobPriority::User, QStringLiteral("STOP, then status"),
        [](JobContext& job) -> Result<QString> {
            Result<Compax3Device*> device = job.family<Compax3Device>();
            if (!device) return device.error();
            (void)job.device()->motionControl()->stopAllMotion();
            const Result<Compax3DriveStatus> status = (*device)->status();
            if (!status) return status.error();
            return status->status.powerless() ? QStringLiteral("powerless")
                                              : QStringLiteral("powered");
        },
        [&after](Result<QString> r) { after = std::move(r); });
    (void)QTest::qWaitFor([&after] { return after.has_value(); }, kWaitMs);
    return after && after->ok() && after->value() == QLatin1String("powered");
}

}  // namespace

class TestCompax3StopGeneration : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aStopInsideEveryStepOfEveryMotionJobLetsNothingMoveAfterIt_data() {
        motionJobRows(motionJobs());
    }
    void aStopInsideEveryStepOfEveryMotionJobLetsNothingMoveAfterIt() {
        QFETCH(int, job);
        const MotionJobUnderTest motion = motionJobs().at(job);
        if (motion.name == QLatin1String("enable") && stopPowersAPowerlessDrive())
            QSKIP(
                "the STOP itself powers a powerless drive (issue 35 item 2, another branch): "
                "an enable it overtakes then finds the drive powered; must pass once that "
                "is fixed");
        stopInsideEveryStep(motion);
    }

    void theStopsOwnWritesAreNoMotion() {
        // A STOP asked while another STOP runs does not hold back the
        // running STOP's writes: they stop, they do not move.
        std::unique_ptr<JobRunner> worker = fresh(true)();
        QVERIFY(worker);
        const StopRun<QString> run = runWithStopAfter<QString>(
            *worker, 1, onDrive([](Compax3Device& d) { return d.motion(Compax3Motion::Stop); }));
        QVERIFY(run.result);
        QVERIFY2(run.result->ok(), qPrintable(run.result->error().message));
        for (const LeftRequest& sent : run.left) QVERIFY2(!sent.motion, qPrintable(sent.label));
    }
};

QTEST_GUILESS_MAIN(TestCompax3StopGeneration)
#include "tst_compax3_stop_generation.moc"
