#pragma once

// Issue 35 item 4: STOP is never out of reach. Escape inside each kind of
// dialog, window and menu of the program while a device moves: one STOP,
// exactly the bytes of a STOP pressed on the window's own button, nothing
// else, and the dialog closed (the menu too). Family-free: a family's test
// says how its device is set moving and adds its own dialogs.
#include "shell_fixture.h"

#include "ui/connection_page.h"
#include "ui/device_session.h"
#include "ui/dialog_stop.h"
#include "ui/live_device_page.h"
#include "ui/main_window.h"
#include "ui/motion_stop.h"
#include "ui/program_stop.h"
#include "ui/stop_bar.h"

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QInputDialog>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QPointer>
#include <QPushButton>
#include <QTest>
#include <QTimer>

#include <functional>
#include <optional>

namespace cambench::test {

// The bytes a session's worker sent since the last clear().
class SentBytes : public QObject {
public:
    explicit SentBytes(DeviceSession* session) {
        connect(&session->worker(), &comm::JobRunner::traffic, this,
                [this](const comm::TrafficEntry& entry) {
                    if (entry.outgoing) m_sent << entry.bytes;
                });
    }
    QList<QByteArray> sent() const { return m_sent; }
    void clear() { m_sent.clear(); }

private:
    QList<QByteArray> m_sent;
};

// Waits until `session`'s line has been quiet for a while (what the jog
// and its pages read has been answered): from then on every byte is the
// test's. Bounded; never a pass/fail threshold.
inline bool waitQuiet(DeviceSession* session) {
    constexpr int kQuietMs = 300;
    QElapsedTimer quiet;
    quiet.start();
    QObject context;
    QObject::connect(&session->worker(), &comm::JobRunner::traffic, &context,
                     [&quiet] { quiet.restart(); });
    return QTest::qWaitFor([&quiet] { return quiet.elapsed() >= kQuietMs; }, kDeviceTimeoutMs);
}

// `window` shows its Connection page instead of `page`: no page polls, and
// once `page`'s last poll has come back the line is the test's.
inline bool leaveForQuietPage(MainWindow* window, LiveDevicePage* page) {
    window->showSection(MainWindow::Connection);
    return QTest::qWaitFor([page] { return page->pollState() == LiveDevicePage::PollState::Idle; },
                           kDeviceTimeoutMs);
}

// A place Escape is pressed in: how a person opens it, and what shows that
// it is open (the modal dialog, the innermost open menu).
struct StopPlace {
    QString name;
    // Opens it. A modal dialog's returns once the dialog is closed again;
    // a job's (the check) may open it later.
    std::function<void()> open;
    std::function<QWidget*()> shown = [] { return QApplication::activeModalWidget(); };
    // What must still hold after it was cancelled (nothing it offers was done).
    std::function<bool()> unchanged = [] { return true; };
};

// The menu `title` ("&File") of `window`'s menu bar, opened as a click on it opens it.
inline StopPlace openMenu(QMainWindow* window, const QString& title, const QString& submenu = {}) {
    StopPlace place;
    place.name = QStringLiteral("menu %1 %2").arg(title, submenu);
    place.open = [window, title, submenu] {
        for (QAction* action : window->menuBar()->actions()) {
            if (action->text() != title || !action->menu()) continue;
            window->menuBar()->setActiveAction(action);
            if (submenu.isEmpty()) return;
            for (QAction* inner : action->menu()->actions())
                if (inner->text() == submenu && inner->menu())
                    inner->menu()->popup(action->menu()->geometry().topRight());
        }
    };
    place.shown = [] { return QApplication::activePopupWidget(); };
    return place;
}

// The entry `text` of the menu `title`, triggered as a click on it does.
inline std::function<void()> menuEntry(QMainWindow* window, const QString& title,
                                       const QString& text) {
    return [window, title, text] {
        for (QAction* menu : window->menuBar()->actions()) {
            if (menu->text() != title || !menu->menu()) continue;
            for (QAction* action : menu->menu()->actions())
                if (action->text() == text) action->trigger();
        }
    };
}

// The dialogs and menus of the shell that can be open while a device of
// `window`'s moves (one device's window, not a machine's).
inline QList<StopPlace> shellStopPlaces(MainWindow* window) {
    DeviceSession* session = window->session();
    const auto online = [session] { return session->isOnline(); };
    QList<StopPlace> places;
    // File -> Open machine...: Qt's own file dialog (not the platform's).
    places << StopPlace{QStringLiteral("file dialog"), menuEntry(window, QStringLiteral("&File"),
                                                                 QStringLiteral("Open &machine…"))};
    // File -> New machine...: an input dialog; cancelled, this window keeps its line.
    places << StopPlace{QStringLiteral("input dialog"), menuEntry(window, QStringLiteral("&File"),
                                                                  QStringLiteral("New mac&hine…"))};
    places.last().unchanged = online;
    // Detect's question; cancelled, the line stays.
    places << StopPlace{QStringLiteral("Detect question"),
                        [window] { window->connectionPage()->detect(); }};
    places.last().unchanged = online;
    // Disconnect's question (what moves, STOP offered); cancelled, the line stays.
    places << StopPlace{QStringLiteral("leave question"),
                        [session] { session->disconnectFromDevice(); }};
    places.last().unchanged = online;
    // Help -> Check this device...: the report, after the check's reads.
    places << StopPlace{
        QStringLiteral("check report"),
        menuEntry(window, QStringLiteral("&Help"), QStringLiteral("&Check this device…"))};
    places << openMenu(window, QStringLiteral("&File"));
    places << openMenu(window, QStringLiteral("&View"), QStringLiteral("&Language"));
    return places;
}

// Opens `place` and presses Escape inside it while the device moves; checks
// that exactly one STOP went out, byte for byte `reference`, with nothing
// else between the key and the STOP's report, and that the place closed.
// `stop` is what reports the STOP (the device's, or its machine's).
inline void escapeStopsFrom(const StopPlace& place, DeviceSession* session, StopControl* stop,
                            const QList<QByteArray>& reference) {
    SentBytes sent(session);
    std::optional<QList<QByteArray>> sentAtReport;
    int started = 0;
    QObject context;
    QObject::connect(stop, &StopControl::stopStarted, &context, [&started] { ++started; });
    QObject::connect(stop, &StopControl::stopFinished, &context,
                     [&] { sentAtReport = sent.sent(); });
    bool inside = false;
    bool closed = false;
    QPointer<QWidget> where;  // a dialog may delete itself on close
    QString dialogStop;
    QTimer watch;
    watch.setInterval(10);
    QObject::connect(&watch, &QTimer::timeout, &context, [&] {
        if (inside) return;
        where = place.shown();
        if (!where) return;
        inside = true;
        watch.stop();
        // A dialog shows its STOP, armed; a menu closes at Escape.
        if (auto* dialog = qobject_cast<QDialog*>(where)) {
            DialogStop* row = DialogStop::of(dialog);
            dialogStop = !row                          ? QStringLiteral("no STOP in the dialog")
                         : !row->button()->isVisible() ? QStringLiteral("its STOP hidden")
                         : !row->button()->isEnabled() ? QStringLiteral("its STOP disabled")
                                                       : QString();
        }
        (void)waitQuiet(session);
        sent.clear();
        QWidget* focus = where->focusWidget() ? where->focusWidget() : where.data();
        QTest::keyClick(focus, Qt::Key_Escape);
        (void)QTest::qWaitFor([&] { return sentAtReport.has_value(); }, kDeviceTimeoutMs);
        const auto gone = [&] {
            return (!where || !where->isVisible()) && !QApplication::activePopupWidget();
        };
        (void)QTest::qWaitFor(gone, kDeviceTimeoutMs);
        closed = gone();
    });
    watch.start();
    place.open();
    QVERIFY2(QTest::qWaitFor([&] { return inside; }, kDeviceTimeoutMs),
             qPrintable(place.name + QStringLiteral(": never open")));
    QVERIFY2(dialogStop.isEmpty(), qPrintable(place.name + QStringLiteral(": ") + dialogStop));
    QVERIFY2(sentAtReport.has_value(), qPrintable(place.name + QStringLiteral(": no STOP")));
    QVERIFY2(closed, qPrintable(place.name + QStringLiteral(": still open after Escape")));
    QCOMPARE(started, 1);
    QCOMPARE(*sentAtReport, reference);
    QVERIFY2(place.unchanged(), qPrintable(place.name + QStringLiteral(": not cancelled")));
}

// The top-level dialog of type T that is open (one shown without exec).
template <class T>
QWidget* openDialog() {
    for (QWidget* window : QApplication::topLevelWidgets())
        if (qobject_cast<T*>(window) && window->isVisible()) return window;
    return nullptr;
}

// What a STOP on `bar` sends now: the bytes every Escape must send.
inline QList<QByteArray> referenceStop(DeviceSession* session, StopBar* bar, StopControl* stop) {
    SentBytes sent(session);
    std::optional<QList<QByteArray>> atReport;
    QObject context;
    QObject::connect(stop, &StopControl::stopFinished, &context, [&] { atReport = sent.sent(); });
    if (!waitQuiet(session)) return {};
    sent.clear();
    bar->button()->click();
    (void)QTest::qWaitFor([&] { return atReport.has_value(); }, kDeviceTimeoutMs);
    return atReport.value_or(QList<QByteArray>());
}

// Nothing the device says moves (powered is not moving).
inline bool nothingMoves(MotionStop* stop, QString* said = nullptr) {
    const Result<QStringList> moving = stop->activeMotion(kDeviceTimeoutMs);
    if (said) *said = moving ? moving->join(QStringLiteral("; ")) : moving.error().message;
    if (!moving) return false;
    for (const QString& line : *moving)
        if (line.contains(QLatin1String("moves"))) return false;
    return true;
}

// For each place: the device set moving by `startMotion`, Escape inside
// the place (escapeStopsFrom), and then nothing of `device` moves.
inline void escapeStopsFromEach(const QList<StopPlace>& places, DeviceSession* session,
                                StopControl* stop, MotionStop* device,
                                const QList<QByteArray>& reference,
                                const std::function<bool()>& startMotion) {
    for (const StopPlace& place : places) {
        QVERIFY2(startMotion(), qPrintable(place.name));
        escapeStopsFrom(place, session, stop, reference);
        if (QTest::currentTestFailed()) return;
        QString said;
        QVERIFY2(nothingMoves(device, &said), qPrintable(place.name + QLatin1String(": ") + said));
    }
}

// One device's window: Escape in each of the shell's places and in the
// family's `ownPlace`, each while `startMotion` has the device moving.
inline void escapeStopsEverywhereIn(MainWindow* window, const StopPlace& ownPlace,
                                    const std::function<bool()>& startMotion) {
    DeviceSession* session = window->session();
    MotionStop* stop = session->motionStop();
    // A platform's file dialog would never pass Escape on.
    QVERIFY(QCoreApplication::testAttribute(Qt::AA_DontUseNativeDialogs));
    QVERIFY(startMotion());
    const QList<QByteArray> reference = referenceStop(session, window->stopBar(), stop);
    QVERIFY(!reference.isEmpty());
    QString said;
    QVERIFY2(nothingMoves(stop, &said), qPrintable(said));
    escapeStopsFromEach(shellStopPlaces(window) << ownPlace, session, stop, stop, reference,
                        startMotion);
}

}  // namespace cambench::test
