#pragma once

#include "ui/main_window.h"
#include "ui/shell.h"
#include "ui/workspace.h"
#include "ui/cameditor/cam_document.h"

#include <QSignalSpy>
#include <QTest>

#include <memory>

namespace cambench::test {

// Bounds a wait on the simulator; never a pass/fail threshold.
constexpr int kDeviceTimeoutMs = 60000;

// A shell on the in-process simulator, connected through the real
// CommWorker, with identity and program 0 read. Unthrottled: the tests
// need the behaviour, not the baud rate.
inline std::unique_ptr<Shell> startOnSimulator(const QString& port = QStringLiteral("sim:throttle=0")) {
    auto shell = std::make_unique<Shell>();
    shell->start(port);
    // The result of the start sequence arrives through the event loop.
    QSignalSpy loaded(shell->window(), &MainWindow::loaded);
    if (!loaded.wait(kDeviceTimeoutMs) || !loaded.first().first().toBool()) return nullptr;
    return shell;
}

// Lets queued reads (dead times, settings, users) of the start finish.
inline bool waitForSections(Shell& shell) {
    Workspace* ws = shell.workspace();
    return QTest::qWaitFor([ws] { return ws->outputSettingsKnown() && ws->settingsKnown() && !ws->users().isEmpty(); },
                           kDeviceTimeoutMs);
}

}  // namespace cambench::test
