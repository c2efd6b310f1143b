#pragma once

// A jogging MC-1 axis for the GUI tests of the STOP (the MC200 V2 simulator).
#include "../shell/shell_fixture.h"

#include "ui/mc1/mc1_axes_page.h"

#include <QLabel>
#include <QPushButton>

namespace cambench::test {

// The axis shown on `axes` jogs + (Jog + clicked and confirmed as a person
// does, the page shown in `window`); true once the page says so.
inline bool jogPlus(MainWindow* window, Mc1AxesPage* axes) {
    window->showPage(axes);
    if (!QTest::qWaitFor([axes] { return axes->freshness()->isLive(); }, kDeviceTimeoutMs))
        return false;
    {
        const auto yes = answerConfirmation(true);
        axes->findChild<QPushButton*>(QStringLiteral("mc1JogPlus"))->click();
    }
    return QTest::qWaitFor(
        [axes] { return axes->stateLabel()->text().contains(QLatin1String("jogging +")); },
        kDeviceTimeoutMs);
}

}  // namespace cambench::test
