#include "motion_stop.h"

#include "clock_time.h"
#include "device_session.h"
#include "shell_log.h"

#include <QEventLoop>
#include <QTimer>

#include <algorithm>
#include <memory>
#include <optional>

namespace cambench {

using comm::MotionStopLine;
using comm::MotionStopReport;

namespace {

QString stopTitle() {
    return MotionStop::tr("STOP");
}
QString askTitle() {
    return MotionStop::tr("Ask what moves");
}
const QString kAvailabilityTitle = QStringLiteral("motion control?");

}  // namespace

QStringList MotionStop::jobTitles() {
    return {stopTitle(), askTitle(), kAvailabilityTitle};
}

MotionStop::MotionStop(DeviceSession* session) : StopControl(session), m_session(session) {
    connect(session, &DeviceSession::stateChanged, this, [this](comm::ConnectionState state) {
        // What was known of the motion was the device's on the line before.
        if (state != comm::ConnectionState::Connected) setMotion(Motion::Unknown, {});
        switch (state) {
            case comm::ConnectionState::Connected:
                askAvailability();
                break;
            case comm::ConnectionState::Connecting:
                // A connect the person asked for may reach another device; a
                // retry after a lost line keeps the STOP shown (disabled):
                // the machine may still move.
                if (!m_session->isRetrying()) setAvailable(false);
                break;
            case comm::ConnectionState::Disconnected:
                if (!m_session->wantsConnection()) setAvailable(false);
                break;
            case comm::ConnectionState::Lost:
                Q_EMIT availabilityChanged();  // shown, no longer armed
                break;
        }
    });
    // Another identity (a bus device chosen, the device checked after a
    // connect) may be another kind of device.
    connect(session, &DeviceSession::deviceCheckedChanged, this, [this](bool checked) {
        if (checked) askAvailability();
    });
    connect(session, &DeviceSession::targetChanged, this, [this] {
        setMotion(Motion::Unknown, {});
        askAvailability();
    });
    connect(this, &StopControl::stopFinished, this, [this](const MotionStopReport& report) {
        const QString at = clockTime(lastStopTime().time());
        if (report.allAcknowledged())
            setMotion(Motion::Unknown, tr("STOP acknowledged at %1").arg(at));
        else
            setMotion(Motion::MayMove, tr("may move: STOP NOT acknowledged at %1").arg(at));
    });
}

void MotionStop::setMotion(Motion motion, const QString& text) {
    if (m_motion == motion && m_motionText == text) return;
    m_motion = motion;
    m_motionText = text;
    Q_EMIT motionChanged();
}

void MotionStop::noteLiveStatus(const QObject* page, Motion motion, const QString& what) {
    m_liveFrom = page;
    m_liveAt = QTime::currentTime();
    switch (motion) {
        case Motion::Moving:
            setMotion(motion, tr("moving (%1)").arg(what));
            break;
        case Motion::Standing:
            setMotion(motion, tr("standing (%1)").arg(what));
            break;
        case Motion::Unknown:
            // A "moving" read before is no longer known; a STOP's or a
            // move's note stays until a status says more.
            if (m_motion == Motion::Moving || m_motion == Motion::Standing)
                setMotion(Motion::Unknown, {});
            break;
        case Motion::MayMove:
            setMotion(motion, tr("may move (%1)").arg(what));
            break;
    }
}

void MotionStop::noteLiveStatusOld(const QObject* page) {
    if (page != m_liveFrom) return;
    const QString at = clockTime(m_liveAt);
    if (m_motion == Motion::Moving)
        setMotion(Motion::MayMove, tr("may move: moving when last read at %1").arg(at));
    else if (m_motion == Motion::Standing)
        setMotion(Motion::Unknown, {});
}

void MotionStop::noteMotionSent(const QString& what) {
    if (m_motion == Motion::Moving) return;  // the live status says more
    setMotion(Motion::MayMove,
              tr("may move: %1 sent at %2").arg(what, clockTime(QTime::currentTime())));
}

bool MotionStop::armed() const {
    return m_available && m_session->isOnline();
}

void MotionStop::setAvailable(bool available) {
    ++m_asked;  // an answer still on its way is about the line before
    if (m_available == available) {
        Q_EMIT availabilityChanged();  // armed() may have changed with the line
        return;
    }
    m_available = available;
    qCInfo(shellLog) << "STOP" << (available ? "shown" : "hidden");
    Q_EMIT availabilityChanged();
}

void MotionStop::askAvailability() {
    const quint64 asked = ++m_asked;
    // Urgent, and it touches no line: the STOP shows at once, also while a
    // long job runs.
    m_session->worker().run<bool>(
        this, comm::JobPriority::Urgent, kAvailabilityTitle,
        [](comm::JobContext& job) {
            return job.device() != nullptr && job.device()->motionControl() != nullptr;
        },
        [this, asked](bool canMove) {
            if (asked != m_asked) return;
            setAvailable(canMove);
        });
}

void MotionStop::stopAll() {
    if (m_machine) {
        m_machine->stopAll();
        return;
    }
    stopThisDevice();
}

void MotionStop::raiseStopGeneration() {
    m_session->worker().raiseStopGeneration();
}

void MotionStop::stopThisDevice() {
    // At once, before anything else: no motion of a job asked before now
    // leaves, also while the STOP's own job waits for the line.
    raiseStopGeneration();
    if (!m_available) return;
    qCInfo(shellLog) << "STOP pressed";
    // A move that waits for the line must not run after the STOP; the
    // running job (a backup) is only paused for it.
    m_session->worker().dropQueued();
    m_stopRunning = true;
    Q_EMIT stopStarted();
    const QString device = tr("The device");
    const QString notConnected = tr("not connected: the STOP was not sent");
    const QString cannotMove = tr("it has nothing CamBench can stop");
    m_session->worker().run<MotionStopReport>(
        this, comm::JobPriority::Urgent, stopTitle(),
        [device, notConnected, cannotMove](comm::JobContext& job) {
            comm::DeviceConnection* connection = job.device();
            comm::MotionControl* motion = connection ? connection->motionControl() : nullptr;
            if (motion) return motion->stopAllMotion();
            MotionStopReport nothing;
            nothing.lines << MotionStopLine{device, false, connection ? cannotMove : notConnected};
            return nothing;
        },
        [this](MotionStopReport report) {
            m_stopRunning = false;
            qCInfo(shellLog) << "STOP done:" << reportText(report);
            finishStop(report);
        });
}

namespace {

// Runs `start` (which submits a job answering into the given setter) and
// waits for the answer at most `timeoutMs` in a local event loop. An answer
// that comes later goes nowhere: its context is gone.
template <class T>
std::optional<T> waitForAnswer(int timeoutMs,
                               const std::function<void(QObject*, std::function<void(T)>)>& start) {
    QEventLoop loop;
    QObject context;
    std::optional<T> answer;
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    start(&context, [&answer, &loop](T value) {
        answer = std::move(value);
        loop.quit();
    });
    if (!answer) loop.exec();
    return answer;
}

}  // namespace

Result<QStringList> MotionStop::activeMotion(int timeoutMs) {
    if (!armed()) return Error::communication(tr("the device is not connected"));
    const QString noMotion = tr("the device has nothing CamBench can stop");
    const std::optional<Result<QStringList>> answer = waitForAnswer<Result<QStringList>>(
        timeoutMs,
        [this, noMotion](QObject* context, std::function<void(Result<QStringList>)> done) {
            // Queries only, ahead of a running job's next request.
            m_session->worker().run<Result<QStringList>>(
                context, comm::JobPriority::Urgent, askTitle(),
                [noMotion](comm::JobContext& job) -> Result<QStringList> {
                    comm::DeviceConnection* connection = job.device();
                    comm::MotionControl* motion =
                        connection ? connection->motionControl() : nullptr;
                    if (!motion) return Error::communication(noMotion);
                    return motion->activeMotion();
                },
                std::move(done));
        });
    if (!answer) return Error::communication(tr("no answer within %1 s").arg(timeoutMs / 1000.0));
    return *answer;
}

Result<MotionStopReport> MotionStop::stopAndWait(int timeoutMs) {
    const std::optional<MotionStopReport> report = waitForAnswer<MotionStopReport>(
        timeoutMs, [this](QObject* context, std::function<void(MotionStopReport)> done) {
            connect(this, &MotionStop::stopFinished, context,
                    [done](const MotionStopReport& finished) { done(finished); });
            stopAll();
        });
    if (!report)
        return Error::communication(
            tr("no report of the STOP within %1 s").arg(timeoutMs / 1000.0));
    return *report;
}

QString MotionStop::reportSummary(const MotionStopReport& report) {
    const bool noneSent =
        std::all_of(report.lines.cbegin(), report.lines.cend(),
                    [](const MotionStopLine& line) { return line.nothingToStop; });
    if (report.allAcknowledged() && noneSent)
        return tr("Nothing to stop: nothing was powered, and nothing was sent.");
    if (report.allAcknowledged()) return tr("STOP acknowledged by every axis and drive.");
    return tr("STOP NOT acknowledged everywhere – use the machine's emergency stop.");
}

QString MotionStop::reportText(const MotionStopReport& report) {
    QStringList lines;
    for (const MotionStopLine& line : report.lines) {
        if (line.absent) {  // no alarm: there is nothing to stop
            lines << tr("%1: %2").arg(line.what, line.detail);
            continue;
        }
        QString text =
            line.acknowledged
                ? tr("%1: acknowledged").arg(line.what)
                : tr("%1: NOT acknowledged – use the machine's emergency stop").arg(line.what);
        if (line.nothingToStop) text = tr("%1: not powered, nothing to stop").arg(line.what);
        if (!line.detail.isEmpty()) text += QStringLiteral(" – ") + line.detail;
        lines << text;
    }
    if (lines.isEmpty())
        lines << tr("Nothing answered the STOP – use the machine's emergency stop");
    return lines.join(QLatin1Char('\n'));
}

}  // namespace cambench
