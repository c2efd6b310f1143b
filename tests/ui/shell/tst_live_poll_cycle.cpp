// Issue 27, item 6 ("stale is stale everywhere"): the shell's live
// machinery every family's live pages use - a poll cycle spent on the line
// without an answer makes a page's values stale, one spent queued behind a
// long job pauses them and names the job, a page not shown is paused; its
// live values are greyed and say so. Driven cycle by cycle (tick()), on the
// real worker against the simulator, with polls held on the line by the
// test: no clock decides anything here. The device is a fake one
// (tests/family/): the machinery is the shell's, whatever the family.
#include "fake_shell_fixture.h"

#include "live_value_checks.h"

#include "ui/device_session.h"
#include "ui/live_device_page.h"
#include "ui/live_freshness.h"
#include "ui/live_poll_cycle.h"

#include <QLabel>
#include <QThread>

#include <atomic>

using namespace cambench;
using namespace cambench::test;

namespace {

// Holds a job on the line until released (and always when it goes away,
// so that a failed check never leaves the worker waiting).
class Gate {
public:
    ~Gate() { open(); }
    void open() { m_open->store(true); }
    std::shared_ptr<std::atomic_bool> flag() const { return m_open; }
    static void waitFor(const std::shared_ptr<std::atomic_bool>& open,
                        comm::JobContext* job = nullptr) {
        while (!open->load()) {
            if (job) job->progress(0, 0);
            QThread::msleep(1);
        }
    }

private:
    std::shared_ptr<std::atomic_bool> m_open = std::make_shared<std::atomic_bool>(false);
};

// A live page whose poll waits at its gate (and reports progress while it
// waits when told to: answers arriving).
class GatedPage : public LiveDevicePage {
public:
    GatedPage(DeviceSession* session) : LiveDevicePage(session), value(new QLabel(this)) {
        value->setText(QStringLiteral("42"));
        addLiveValue(value);
        freshnessLine()->setParent(this);
    }
    QString sectionTitle() const override { return QStringLiteral("Gated"); }
    bool poll() override {
        ++polls;
        auto open = gate->flag();
        const bool progress = withProgress;
        runPoll<comm::DeviceConnection, int>(
            QStringLiteral("Gated poll"),
            [open, progress](comm::DeviceConnection&, comm::JobContext& job) -> Result<int> {
                Gate::waitFor(open, progress ? &job : nullptr);
                return 1;
            },
            [this](const int&) { ++answers; }, QStringLiteral("gated"));
        return true;
    }
    QLabel* freshnessText() { return freshnessLine(); }

    QLabel* value;
    std::unique_ptr<Gate> gate = std::make_unique<Gate>();
    bool withProgress = false;
    int polls = 0;
    int answers = 0;
};

// The page's `answers`th poll answered: its values live and not greyed.
bool liveAfter(const GatedPage& page, int answers) {
    return QTest::qWaitFor([&] { return page.answers == answers; }, kDeviceTimeoutMs) &&
           page.freshness()->state() == LiveFreshness::State::Live && !greyed(page.value);
}

}  // namespace

class LivePollCycleTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QVERIFY(setUpWithTheFakeFamily()); }

    void aCycleOnTheLineWithoutAnAnswerMakesTheValuesStale() {
        std::unique_ptr<Shell> shell = startOnFake();
        QVERIFY(shell);
        DeviceSession* session = shell->session();
        GatedPage page(session);
        // An hour a cycle: only the test's tick() makes cycles.
        LivePollCycle cycle(session, 3600 * 1000);
        cycle.setShown(&page);
        QCOMPARE(page.polls, 1);
        QVERIFY(
            QTest::qWaitFor([&] { return page.pollState() == LiveDevicePage::PollState::OnLine; },
                            kDeviceTimeoutMs));
        QVERIFY(greyed(page.value));  // nothing read yet

        // The first answer: live, not greyed.
        page.gate->open();
        QVERIFY(liveAfter(page, 1));
        QVERIFY(page.value->toolTip().isEmpty());
        const QString answeredAt = page.freshness()->lastAnswerText();

        // The next poll stays on the line a whole cycle: stale, greyed,
        // "no answer since" the last answer; no second poll is queued.
        page.gate = std::make_unique<Gate>();
        cycle.tick();
        QCOMPARE(page.polls, 2);
        QVERIFY(
            QTest::qWaitFor([&] { return page.pollState() == LiveDevicePage::PollState::OnLine; },
                            kDeviceTimeoutMs));
        cycle.tick();
        QCOMPARE(page.polls, 2);
        QCOMPARE(page.freshness()->state(), LiveFreshness::State::Stale);
        QCOMPARE(session->freshness()->state(), LiveFreshness::State::Stale);
        QVERIFY(greyed(page.value));
        QCOMPARE(page.value->toolTip(), QStringLiteral("No answer since %1").arg(answeredAt));
        QCOMPARE(page.freshnessText()->text(),
                 QStringLiteral("No answer since %1").arg(answeredAt));
        QCOMPARE(page.freshness()->valueNote(),
                 QStringLiteral("no answer since %1").arg(answeredAt));

        // The answer comes after all: live again.
        page.gate->open();
        QVERIFY(liveAfter(page, 2));
    }

    void answersArrivingAreSlowNotSilent() {
        std::unique_ptr<Shell> shell = startOnFake();
        QVERIFY(shell);
        GatedPage page(shell->session());
        page.withProgress = true;
        LivePollCycle cycle(shell->session(), 3600 * 1000);
        cycle.setShown(&page);
        QVERIFY(
            QTest::qWaitFor([&] { return page.pollState() == LiveDevicePage::PollState::OnLine; },
                            kDeviceTimeoutMs));
        // Progress of the poll since the last cycle: not a missed cycle.
        QSignalSpy progress(&shell->session()->worker(), &comm::JobRunner::jobProgress);
        QVERIFY(progress.wait(kDeviceTimeoutMs));
        QCoreApplication::processEvents();
        cycle.tick();
        QVERIFY(page.freshness()->state() != LiveFreshness::State::Stale);
        page.gate->open();
        QVERIFY(liveAfter(page, 1));
    }

    void aPollQueuedBehindABackupPausesTheValues() {
        std::unique_ptr<Shell> shell = startOnFake();
        QVERIFY(shell);
        DeviceSession* session = shell->session();
        GatedPage page(session);
        page.gate->open();
        LivePollCycle cycle(session, 3600 * 1000);
        cycle.setShown(&page);
        QVERIFY(liveAfter(page, 1));
        const QString answeredAt = page.freshness()->lastAnswerText();

        // A long job holds the line: the next poll waits behind it.
        Gate backup;
        bool backupDone = false;
        QSignalSpy started(&session->worker(), &comm::JobRunner::jobStarted);
        session->run<comm::DeviceConnection, int>(
            &page, QStringLiteral("Back up controller"),
            [open = backup.flag()](comm::DeviceConnection&, comm::JobContext&) -> Result<int> {
                Gate::waitFor(open);
                return 1;
            },
            [&](Result<int>) { backupDone = true; });
        // The backup reaches the line.
        QVERIFY(QTest::qWaitFor(
            [&] {
                return !started.isEmpty() &&
                       started.last().at(1).toString() == QLatin1String("Back up controller");
            },
            kDeviceTimeoutMs));
        QCoreApplication::processEvents();
        cycle.tick();  // a poll queued
        QCOMPARE(page.polls, 2);
        QCOMPARE(page.pollState(), LiveDevicePage::PollState::Queued);
        cycle.tick();  // a whole cycle queued: paused, naming the job
        QCOMPARE(page.freshness()->state(), LiveFreshness::State::Paused);
        QCOMPARE(page.freshness()->valueNote(),
                 QStringLiteral("paused (Back up controller), read %1").arg(answeredAt));
        QCOMPARE(page.freshnessText()->text(),
                 QStringLiteral("Paused (Back up controller); values of %1").arg(answeredAt));
        QVERIFY(greyed(page.value));

        backup.open();
        QVERIFY(liveAfter(page, 2));
        QVERIFY(QTest::qWaitFor([&] { return backupDone; }, kDeviceTimeoutMs));
    }

    void aPageNoLongerShownIsPaused() {
        std::unique_ptr<Shell> shell = startOnFake();
        QVERIFY(shell);
        GatedPage first(shell->session());
        GatedPage second(shell->session());
        first.gate->open();
        second.gate->open();
        LivePollCycle cycle(shell->session(), 3600 * 1000);
        cycle.setShown(&first);
        QVERIFY(QTest::qWaitFor([&] { return first.answers == 1; }, kDeviceTimeoutMs));
        cycle.setShown(&second);
        QCOMPARE(first.freshness()->state(), LiveFreshness::State::Paused);
        QVERIFY(first.freshnessText()->text().startsWith(QLatin1String("Not polled now")));
        QVERIFY(greyed(first.value));
        QVERIFY(QTest::qWaitFor([&] { return second.answers == 1; }, kDeviceTimeoutMs));
        cycle.tick();
        QCOMPARE(first.polls, 1);  // only the shown page polls
        QCOMPARE(second.polls, 2);
    }
};

QTEST_MAIN(LivePollCycleTest)
#include "tst_live_poll_cycle.moc"
