#pragma once

// What the CamCon's GUI tests share beside the shell's fixture: its window
// and workspace, the gates of its sections, the reads of the start, the
// question before a read replaces edits, one row per protocol.
#include "../shell/shell_fixture.h"

#include "ui/camcon/camcon_gui.h"
#include "ui/camcon/camcon_window.h"
#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/capability_gate.h"
#include "ui/camcon/replace_edits_dialog.h"
#include "ui/camcon/users_page.h"
#include "ui/camcon/workspace.h"

namespace cambench::test {

// The gate of the section that shows `page`, or nullptr for an ungated one.
inline CapabilityGate* gateOf(MainWindow* window, QWidget* page) {
    for (CapabilityGate* gate : window->findChildren<CapabilityGate*>())
        if (gate->page() == page) return gate;
    return nullptr;
}

// Lets queued reads (dead times, settings, users where the protocol has
// them) of the start finish.
inline bool waitForSections(Shell& shell) {
    Workspace* ws = camConWorkspace(shell);
    CapabilityGate* users = gateOf(shell.window(), camConWindow(shell.window())->usersPage());
    return QTest::qWaitFor(
        [ws, users] {
            return ws->outputSettingsKnown() && ws->settings().known() &&
                   (!users->isAvailable() || ws->users().size() > 0);
        },
        kDeviceTimeoutMs);
}

// "Keep my edits / take the device's values": the same for every section.
inline std::unique_ptr<NextDialog<ReplaceEditsDialog>> answerReplaceEdits(bool keepEdits) {
    return std::make_unique<NextDialog<ReplaceEditsDialog>>(
        [keepEdits](ReplaceEditsDialog* dialog) {
            for (EditSection section : dialog->sections()) dialog->choose(section, keepEdits);
            dialog->accept();
        });
}

inline std::unique_ptr<NextDialog<ReplaceEditsDialog>> cancelReplaceEdits() {
    return std::make_unique<NextDialog<ReplaceEditsDialog>>(
        [](ReplaceEditsDialog* dialog) { dialog->reject(); });
}

// The rows of a test that runs once per CamCon protocol.
inline void protocolRows() {
    QTest::addColumn<QString>("protocol");
    for (const char* protocol : {"standard", "3964r-n96", "3964r-e38"})
        QTest::newRow(protocol) << QString::fromLatin1(protocol);
}

}  // namespace cambench::test
