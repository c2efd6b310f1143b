#pragma once

#include "ui/connection_page.h"
#include "ui/main_window.h"
#include "ui/shell.h"

#include <QAbstractButton>
#include <QApplication>
#include <QCoreApplication>
#include <QMessageBox>
#include <QPointer>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <functional>
#include <memory>

namespace cambench::test {

// Bounds a wait on the simulator; never a pass/fail threshold.
constexpr int kDeviceTimeoutMs = 60000;

// The GUI remembers things (QSettings): tests keep theirs apart from the
// user's and start from none. Call in initTestCase().
inline void useTestSettings() {
    QCoreApplication::setOrganizationName(QStringLiteral("CamBench"));
    QCoreApplication::setApplicationName(QStringLiteral("CamBench-tests"));
    QStandardPaths::setTestModeEnabled(true);
    // Each test process its own settings file: under `ctest -j2` two GUI
    // tests shared ~/.qttest's, and one's clear() at its start emptied what
    // the other had just remembered (the MC-1 axes and parameters test under
    // AddressSanitizer read back "" for the table it had loaded).
    static const QTemporaryDir settingsDir;
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settingsDir.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir.path());
    QSettings().clear();
}

// A shell on the in-process simulator, connected through the real
// CommWorker with `protocol` (the simulated device speaks it too), with
// identity and program 0 read. Unthrottled: the tests need the behaviour,
// not the baud rate.
inline std::unique_ptr<Shell> startOnSimulator(
    const QString& port = QStringLiteral("sim:throttle=0"),
    const QString& protocol = QStringLiteral("standard")) {
    auto shell = std::make_unique<Shell>();
    // Spied before the start: the result of the start sequence arrives
    // through the event loop, but the window is made by start().
    shell->start(port, protocol);
    QSignalSpy loaded(shell->window(), &MainWindow::loaded);
    if (!loaded.wait(kDeviceTimeoutMs) || !loaded.first().first().toBool()) return nullptr;
    return shell;
}

// Answers the next modal dialog of type Dialog, whenever it comes up
// (a question asked when a read finishes, say): `answer` gets it.
template <class Dialog>
class NextDialog : public QObject {
public:
    explicit NextDialog(std::function<void(Dialog*)> answer) : m_answer(std::move(answer)) {
        // Polls only to find the dialog; the test's own waits bound the time.
        m_timer.setInterval(10);
        QObject::connect(&m_timer, &QTimer::timeout, this, [this] {
            auto* dialog = qobject_cast<Dialog*>(QApplication::activeModalWidget());
            if (!dialog) return;
            m_timer.stop();
            ++m_answered;
            m_answer(dialog);
        });
        m_timer.start();
    }
    int answered() const { return m_answered; }

private:
    std::function<void(Dialog*)> m_answer;
    QTimer m_timer;
    int m_answered = 0;
};

// Presses the confirmation's action (yes) or Cancel; a box without a
// Cancel gets its first button.
inline std::unique_ptr<NextDialog<QMessageBox>> answerConfirmation(bool yes) {
    return std::make_unique<NextDialog<QMessageBox>>([yes](QMessageBox* box) {
        for (QAbstractButton* button : box->buttons()) {
            const bool isCancel = box->buttonRole(button) == QMessageBox::RejectRole;
            if (isCancel != yes) {
                button->click();
                return;
            }
        }
        box->buttons().first()->click();
    });
}

// The question before leaving a device that may move or whose motion
// cannot be told (ui/motion_leave_question.cpp; a Compax3 always, its
// status word being provisional; an MC200 read through the guessed
// parameter numbers): presses its button named `button`
// ("leaveWithoutStop", "stopThenLeave") when it comes, else cancels it;
// any other message box is left alone.
inline std::unique_ptr<NextDialog<QMessageBox>> answerLeaveQuestion(
    const QString& button = QStringLiteral("leaveWithoutStop")) {
    return std::make_unique<NextDialog<QMessageBox>>([button](QMessageBox* box) {
        if (box->objectName() != QLatin1String("motionLeaveQuestion")) return;
        if (QAbstractButton* pressed = box->findChild<QAbstractButton*>(button))
            pressed->click();
        else
            box->reject();
    });
}

}  // namespace cambench::test
