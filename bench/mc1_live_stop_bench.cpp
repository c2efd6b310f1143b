#include "mc1_live_stop_bench.h"

#include "comm/device/job_runner.h"
#include "comm/engine/request_engine.h"
#include "comm/mc1/mc1_controller.h"
#include "comm/mc1/mc1_protocol.h"
#include "comm/mc1/mc1_telegram.h"
#include "comm/sim/mc1/mc1_simulator.h"
#include "comm/sim/sim_pty_server.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTextStream>
#include <QThread>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <memory>
#include <mutex>

namespace cambench::bench {

namespace {

using namespace cambench::comm;
using Clock = std::chrono::steady_clock;

constexpr int kBaud = 9600;
constexpr int kWaitMs = 60000;  // bounds a hang

enum class Known { AxesAndController, Controller, Nothing };

struct LiveStop {
    int stops = 0;          // stop telegrams (one per line of the report)
    double toLastAck = 0;   // s from STOP asked to the last stop's answer
    double toFirstAck = 0;  // s from STOP asked to the first stop's answer
    bool acknowledged = false;
    QString failure;
};

// Runs the event loop until `done` or the bound.
bool waitFor(const std::function<bool()>& done) {
    QElapsedTimer timer;
    timer.start();
    while (!done() && timer.elapsed() < kWaitMs) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        QThread::msleep(1);
    }
    return done();
}

// Runs `work` as a User job and waits for it.
template <class T>
std::optional<T> runJob(JobRunner& worker, std::function<T(JobContext&)> work) {
    std::optional<T> answer;
    QObject context;
    worker.run<T>(&context, JobPriority::User, QStringLiteral("bench"), std::move(work),
                  [&answer](T value) { answer = std::move(value); });
    waitFor([&answer] { return answer.has_value(); });
    return answer;
}

// RDVAR of V1 straight through the engine: a poll that does not identify
// the controller (the device's own reads would).
Request rdvar() {
    const Mc1Telegram* telegram = mc1Find(Mc1Variant::Mc200V2, Mc1Op::ReadVariable);
    Request request;
    request.label = QStringLiteral("RDVAR");
    request.message = mc1Request(*telegram, mc1LittleEndian(1, 2)).value();
    request.longestReplyBytes = mc1ExpectedAnswer(*telegram, mc1LittleEndian(1, 2)).length;
    return request;
}

LiveStop measure(Known known) {
    LiveStop result;
    SimHostOptions shared;
    shared.throttle = true;
    SimulatedLine line = mc1SimulatedLine(Mc1Variant::Mc200V2, kBaud, shared);
    SimPtyServer pty(*line.endpoint, line.pacer);
    if (const Status opened = pty.open(); !opened) {
        result.failure = opened.error().message;
        return result;
    }
    std::unique_ptr<JobRunner> worker = makeCommWorker();
    ConnectionSettings connection;
    connection.port = pty.slavePath();
    connection.serial.baud = kBaud;
    worker->connectTo(connection, std::make_shared<Mc1ProtocolSettings>());
    if (!waitFor([&worker] { return worker->state() == ConnectionState::Connected; })) {
        result.failure = QStringLiteral("not connected to %1").arg(pty.slavePath());
        return result;
    }
    // What the PC knows before the STOP, and the answers' times from now on.
    auto times = std::make_shared<std::mutex>();
    auto answers = std::make_shared<QList<Clock::time_point>>();
    auto asked = std::make_shared<std::atomic_bool>(false);
    const std::optional<bool> ready =
        runJob<bool>(*worker, [known, times, answers, asked](JobContext& job) {
            auto* device = dynamic_cast<Mc1Device*>(job.device());
            if (!device) return false;
            if (known != Known::Nothing && !device->ensureIdentified()) return false;
            if (known == Known::AxesAndController && !device->axes()) return false;
            device->engine().setIncomingObserver([times, answers, asked](const Incoming& in) {
                if (!asked->load() || in.kind != Incoming::Message || in.message.size() != 1)
                    return;
                const quint8 byte = quint8(in.message.at(0));
                if (byte != kMc1Ack && byte != kMc1Nak) return;
                std::lock_guard lock(*times);
                answers->append(Clock::now());
            });
            return true;
        });
    if (!ready || !*ready) {
        result.failure = QStringLiteral("the controller did not answer before the STOP");
        return result;
    }
    // The poll: RDVAR after RDVAR until the STOP has reported.
    auto polling = std::make_shared<std::atomic_bool>(true);
    QObject context;
    bool pollEnded = false;
    worker->run<bool>(
        &context, JobPriority::Poll, QStringLiteral("poll"),
        [polling](JobContext& job) {
            while (polling->load())
                if (!job.device()->engine().send(rdvar())) return false;
            return true;
        },
        [&pollEnded](bool) { pollEnded = true; });
    QThread::msleep(300);  // the poll is on the line

    // As the GUI asks it (ui/motion_stop.cpp).
    std::optional<MotionStopReport> report;
    const Clock::time_point stopAsked = Clock::now();
    asked->store(true);
    worker->raiseStopGeneration();
    worker->dropQueued();
    worker->run<MotionStopReport>(
        &context, JobPriority::Urgent, QStringLiteral("STOP"),
        [](JobContext& job) { return job.device()->motionControl()->stopAllMotion(); },
        [&report](MotionStopReport done) { report = std::move(done); });
    waitFor([&report] { return report.has_value(); });
    polling->store(false);
    waitFor([&pollEnded] { return pollEnded; });
    if (!report) {
        result.failure = QStringLiteral("no report of the STOP");
        return result;
    }
    result.stops = int(report->lines.size());
    result.acknowledged = report->allAcknowledged();
    std::lock_guard lock(*times);
    if (answers->size() < result.stops) {
        result.failure =
            QStringLiteral("%1 answers to %2 stops").arg(answers->size()).arg(result.stops);
        return result;
    }
    const auto seconds = [stopAsked](Clock::time_point at) {
        return std::chrono::duration<double>(at - stopAsked).count();
    };
    result.toFirstAck = seconds(answers->first());
    result.toLastAck = seconds(answers->at(result.stops - 1));
    return result;
}

}  // namespace

void benchMc1LiveStop() {
    QTextStream out(stdout);
    out << "| STOP on a live line (MC200 V2 with 8 axes, pty, 9600 baud, a poll running) | stops "
           "| to the first ACK | to the last ACK | wire limit of the stops | ratio | all "
           "acknowledged |\n| --- | ---: | ---: | ---: | ---: | ---: | --- |\n";
    const struct {
        QString what;
        Known known;
    } rows[] = {{QStringLiteral("axes known (RDTABLE before)"), Known::AxesAndController},
                {QStringLiteral("axes not known"), Known::Controller},
                {QStringLiteral("axes not known, controller not identified"), Known::Nothing}};
    for (const auto& row : rows) {
        const LiveStop run = measure(row.known);
        if (!run.failure.isEmpty()) {
            out << QStringLiteral("| %1 | failed: %2 | | | | | |\n").arg(row.what, run.failure);
            continue;
        }
        // A stop is 4 bytes out (AXIS_NODATA), 1 back (ACK), 10 bits a byte.
        const double limit = run.stops * 5.0 * 10 / kBaud;
        out << QStringLiteral("| %1 | %2 | %3 s | %4 s | %5 s | %6 | %7 |\n")
                   .arg(row.what)
                   .arg(run.stops)
                   .arg(run.toFirstAck, 0, 'f', 3)
                   .arg(run.toLastAck, 0, 'f', 3)
                   .arg(limit, 0, 'f', 3)
                   .arg(run.toLastAck / limit, 0, 'f', 2)
                   .arg(run.acknowledged ? QStringLiteral("yes") : QStringLiteral("no"));
        out.flush();
    }
}

}  // namespace cambench::bench
