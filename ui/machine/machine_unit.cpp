#include "machine_unit.h"

#include "machine_connection.h"

#include "comm/device/device_connection.h"
#include "comm/device/family_registry.h"
#include "comm/usecases/line_answer.h"
#include "ui/connection_page.h"
#include "ui/device_session.h"
#include "ui/family_gui.h"
#include "ui/main_window.h"
#include "ui/motion_stop.h"
#include "ui/sentence.h"

namespace cambench {

namespace {

QString familyTitle(const QString& familyId) {
    const comm::FamilyInfo* info = comm::FamilyRegistry::instance().find(familyId);
    return info ? QCoreApplication::translate("cambench::comm", info->title.toUtf8().constData())
                : familyId;
}

QString watchTitle() {
    return MachineUnit::tr("Watch the line");
}

// "14:03:07": the time of day, to the second (a cycle is half of one).
QString answerTime(const QDateTime& at) {
    return at.isValid() ? at.toString(QStringLiteral("HH:mm:ss")) : MachineUnit::tr("the connect");
}

}  // namespace

MachineUnit::MachineUnit(MachineDevice device, StopControl* machineStop, QObject* parent)
    : QObject(parent),
      m_device(std::move(device)),
      m_machineStop(machineStop),
      m_session(new DeviceSession(this)),
      m_families(createFamilyGuis(m_session, this)) {
    connect(m_session, &DeviceSession::stateChanged, this, [this](comm::ConnectionState state) {
        // The machine file holds what the device is reached with: also a
        // port or protocol chosen on its Connection page.
        // The identity (the device that belongs here) and the items that
        // change by themselves are the file's, not the connection's: they stay.
        if (state == comm::ConnectionState::Connected) {
            const DeviceIdentity identity = m_device.identity;
            const QStringList volatileItems = m_device.volatileItems;
            m_device =
                machineDeviceFor(m_device.name, m_session->connection(), m_session->protocol());
            m_device.identity = identity;
            m_device.volatileItems = volatileItems;
        }
        lineChanged();
        Q_EMIT changed();
    });
    connect(m_session, &DeviceSession::deviceCheckedChanged, this, [this](bool checked) {
        // The family found its device where the check found none or another
        // (a device swapped back, a bus device chosen): asked again.
        if (checked && (m_check == Check::Another || m_check == Check::Silent)) checkLineAnswer();
        Q_EMIT changed();
    });
    connect(m_session, &DeviceSession::identifyProblemChanged, this, &MachineUnit::changed);
    connect(m_session, &DeviceSession::targetChanged, this, [this] {
        if (m_session->isOnline()) checkLineAnswer();
    });
    connect(m_session->motionStop(), &MotionStop::motionChanged, this, &MachineUnit::changed);
    connect(&m_session->worker(), &comm::JobRunner::jobStarted, this,
            [this](quint64 id, const QString&) {
                if (id == m_watchJob) m_watchOnLine = true;
            });
    m_watch.setInterval(kWatchMs);
    connect(&m_watch, &QTimer::timeout, this, &MachineUnit::watchLine);
    for (FamilyGui* family : m_families) {
        connect(family, &FamilyGui::titleChanged, this, &MachineUnit::changed);
        connect(family, &FamilyGui::identityChanged, this, &MachineUnit::changed);
    }
}

MachineUnit::~MachineUnit() {
    // Its pages point at this unit's session and families.
    delete m_window;
}

MainWindow* MachineUnit::window() const {
    return m_window;
}

MainWindow* MachineUnit::createWindow() {
    delete m_window;
    m_window = new MainWindow(m_session, m_families, m_machineStop);
    // A part of the machine's window, not a window of its own.
    m_window->setWindowFlags(Qt::Widget);
    // The machine file names the device on a bus: never another number.
    m_window->connectionPage()->setFindsBusDevice(false);
    // The line's watch runs all the time: not a job for the progress bar.
    m_window->addQuietJobTitle(watchTitle());
    connect(m_window, &MainWindow::languageRequested, this, &MachineUnit::languageRequested,
            Qt::QueuedConnection);
    return m_window;
}

void MachineUnit::connectDevice() {
    if (!m_window) createWindow();
    // A device added to the machine: its Connection page says how.
    if (m_device.option(QStringLiteral("port")).isEmpty()) return;
    const Result<MachineConnection> connection = machineConnection(m_device);
    if (!connection) {
        m_problem = connection.error().message;
        Q_EMIT changed();
        return;
    }
    m_problem.clear();
    m_window->connectionPage()->showConnection(connection->connection, *connection->protocol);
    m_window->connectAndLoad();
}

void MachineUnit::lineChanged() {
    m_checkJob = 0;
    m_watchJob = 0;
    m_watchOnLine = false;
    if (m_session->state() == comm::ConnectionState::Connected) {
        checkLineAnswer();
        m_watch.start();
        return;
    }
    m_watch.stop();
    setCheck(Check::Unchecked);
}

void MachineUnit::setCheck(Check check, const QString& text) {
    if (m_check == check && m_checkText == text) return;
    m_check = check;
    m_checkText = text;
    Q_EMIT changed();
}

void MachineUnit::checkLineAnswer() {
    if (m_checkJob != 0) return;
    // Asked again about another device or none: it stays red until a
    // device that belongs here answers (no amber flicker between checks).
    if (m_check != Check::Another && m_check != Check::Silent) setCheck(Check::Checking);
    m_recheckTicks = 0;
    using usecases::LineAnswer;
    const quint64 job = m_session->worker().run<Result<LineAnswer>>(
        this, comm::JobPriority::User, tr("Check which device answers"),
        [](comm::JobContext& context) -> Result<LineAnswer> {
            if (!context.device()) return Error::communication(tr("not connected"));
            return usecases::lineAnswer(*context.device(), true);
        },
        [this](Result<LineAnswer> answer) {
            if (!std::exchange(m_checkJob, 0)) return;  // the line changed since
            if (!answer) {
                // Cancelled (a STOP, a reconnect): asked again in a few cycles.
                if (m_check == Check::Checking) setCheck(Check::Unchecked);
                return;
            }
            if (!answer->identified) {
                setCheck(answer->heardOther ? Check::Another : Check::Silent,
                         answer->heardOther
                             ? tr("another device answers: no %1 identifies itself (%2)")
                                   .arg(familyTitle(m_device.family), asSentence(answer->problem))
                             : tr("no answer: %1").arg(asSentence(answer->problem)));
                return;
            }
            m_lastAnswer = QDateTime::currentDateTime();
            if (m_device.identity.known() && m_device.identity != answer->identity) {
                setCheck(Check::Another, anotherDeviceText(m_device.identity, answer->identity));
                return;
            }
            // The first device seen here is the one the machine file records.
            if (!m_device.identity.known()) m_device.identity = answer->identity;
            m_answerLine = answer->text;
            setCheck(Check::Confirmed);
        });
    m_checkJob = job;
}

void MachineUnit::watchLine() {
    ++m_watchCycles;
    if (!m_session->isOnline() || m_checkJob != 0) return;
    if (m_check != Check::Confirmed) {
        // Another device or none: asked again every few cycles, queries only.
        constexpr int kRecheckTicks = 4;
        if (++m_recheckTicks >= kRecheckTicks) checkLineAnswer();
        return;
    }
    if (m_watchJob != 0) {
        // The query has been on the line two whole cycles unanswered.
        constexpr int kSilentTicks = 2;
        if (m_watchOnLine && ++m_unansweredTicks >= kSilentTicks)
            setCheck(Check::Silent, tr("no answer since %1").arg(answerTime(m_lastAnswer)));
        return;
    }
    using usecases::LineAnswer;
    m_watchOnLine = false;
    m_unansweredTicks = 0;
    const quint64 ticket = ++m_watchTicket;
    m_watchJob = m_session->worker().run<Result<LineAnswer>>(
        this, comm::JobPriority::Poll, watchTitle(),
        [](comm::JobContext& context) -> Result<LineAnswer> {
            if (!context.device()) return Error::communication(tr("not connected"));
            return usecases::lineAnswer(*context.device(), false);
        },
        [this, ticket](Result<LineAnswer> answer) {
            if (ticket != m_watchTicket || m_watchJob == 0) return;  // the line changed since
            watchAnswered(answer);
        },
        QStringLiteral("machine-line-watch"));
}

void MachineUnit::watchAnswered(const Result<usecases::LineAnswer>& answer) {
    m_watchJob = 0;
    m_watchOnLine = false;
    if (!answer || m_checkJob != 0) return;  // dropped by a STOP; or a full check runs
    if (!answer->identified) {
        setCheck(answer->heardOther ? Check::Another : Check::Silent,
                 answer->heardOther
                     ? tr("another device answers: no %1 identifies itself (%2)")
                           .arg(familyTitle(m_device.family), asSentence(answer->problem))
                     : tr("no answer since %1: %2")
                           .arg(answerTime(m_lastAnswer), asSentence(answer->problem)));
        return;
    }
    m_lastAnswer = QDateTime::currentDateTime();
    // Another line than the confirmed device's: who it is, in full.
    if (answer->text != m_answerLine) {
        checkLineAnswer();
        return;
    }
    setCheck(Check::Confirmed);
}

MachineUnit::Lamp MachineUnit::lamp() const {
    if (!m_problem.isEmpty()) return Lamp::Gone;
    switch (m_session->state()) {
        case comm::ConnectionState::Connected:
            if (m_check == Check::Another) return Lamp::AnotherDevice;
            if (m_check == Check::Silent) return Lamp::Gone;
            // The family's own check found none of its devices.
            if (!m_session->identifyProblem().isEmpty()) return Lamp::Gone;
            if (m_check != Check::Confirmed || !m_session->deviceChecked()) return Lamp::Connecting;
            return m_session->motionStop()->motion() == MotionStop::Motion::Moving
                       ? Lamp::Moving
                       : Lamp::Connected;
        case comm::ConnectionState::Connecting:
            return m_session->isRetrying() ? Lamp::Gone : Lamp::Connecting;
        case comm::ConnectionState::Lost:
            return Lamp::Gone;
        case comm::ConnectionState::Disconnected:
            return m_session->isRetrying() || !m_session->lastMessage().isEmpty() ? Lamp::Gone
                                                                                  : Lamp::Offline;
    }
    return Lamp::Offline;
}

QString MachineUnit::stateText() const {
    if (!m_problem.isEmpty()) return tr("not opened: %1").arg(m_problem);
    switch (lamp()) {
        case Lamp::Connected:
        case Lamp::Moving: {
            const QString motion = m_session->motionStop()->motionText();
            return motion.isEmpty() ? tr("connected") : tr("connected, %1").arg(motion);
        }
        case Lamp::AnotherDevice:
            return m_checkText;
        case Lamp::Connecting:
            return m_session->isOnline() ? tr("checking which device answers…") : tr("connecting…");
        case Lamp::Gone:
            if (m_session->isOnline())
                return m_check == Check::Silent
                           ? m_checkText
                           : tr("did not identify itself: %1")
                                 .arg(asSentence(m_session->identifyProblem()));
            if (m_session->isRetrying() || m_session->state() == comm::ConnectionState::Lost)
                return tr("gone, retrying: %1").arg(m_session->lastMessage());
            return tr("not connected: %1").arg(m_session->lastMessage());
        case Lamp::Offline:
            break;
    }
    if (m_device.option(QStringLiteral("port")).isEmpty())
        return tr("not connected yet: choose its port on its Connection page");
    return tr("offline");
}

int MachineUnit::unwrittenCount() const {
    int count = 0;
    for (const FamilyGui* family : m_families) count += family->unwrittenCount();
    return count;
}

}  // namespace cambench
