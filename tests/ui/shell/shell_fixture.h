#pragma once

#include "ui/cameditor/cam_document.h"
#include "ui/capability_gate.h"
#include "ui/connection_page.h"
#include "ui/main_window.h"
#include "ui/shell.h"
#include "ui/users_page.h"
#include "ui/workspace.h"

#include <QSignalSpy>
#include <QTest>

#include <memory>

namespace cambench::test {

// Bounds a wait on the simulator; never a pass/fail threshold.
constexpr int kDeviceTimeoutMs = 60000;

// A shell on the in-process simulator, connected through the real
// CommWorker with `protocol` (the simulated device speaks it too), with
// identity and program 0 read. Unthrottled: the tests need the behaviour,
// not the baud rate.
inline std::unique_ptr<Shell> startOnSimulator(
    const QString& port = QStringLiteral("sim:throttle=0"),
    const QString& protocol = QStringLiteral("standard")) {
    auto shell = std::make_unique<Shell>();
    shell->start(QString());
    shell->window()->connectionPage()->setPort(port);
    shell->window()->connectionPage()->setProtocol(protocol);
    // The result of the start sequence arrives through the event loop.
    QSignalSpy loaded(shell->window(), &MainWindow::loaded);
    shell->window()->connectAndLoad(0);
    if (!loaded.wait(kDeviceTimeoutMs) || !loaded.first().first().toBool()) return nullptr;
    return shell;
}

// The gate of the section that shows `page`, or nullptr for an ungated one.
inline CapabilityGate* gateOf(MainWindow* window, QWidget* page) {
    for (CapabilityGate* gate : window->findChildren<CapabilityGate*>())
        if (gate->page() == page) return gate;
    return nullptr;
}

// Lets queued reads (dead times, settings, users where the protocol has
// them) of the start finish.
inline bool waitForSections(Shell& shell) {
    Workspace* ws = shell.workspace();
    CapabilityGate* users = gateOf(shell.window(), shell.window()->usersPage());
    return QTest::qWaitFor(
        [ws, users] {
            return ws->outputSettingsKnown() && ws->settingsKnown() &&
                   (!users->isAvailable() || !ws->users().isEmpty());
        },
        kDeviceTimeoutMs);
}

// The rows of a test that runs once per CamCon protocol.
inline void protocolRows() {
    QTest::addColumn<QString>("protocol");
    for (const char* protocol : {"standard", "3964r-n96", "3964r-e38"})
        QTest::newRow(protocol) << QString::fromLatin1(protocol);
}

}  // namespace cambench::test
