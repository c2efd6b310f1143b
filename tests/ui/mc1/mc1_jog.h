#pragma once

// A jogging MC-1 axis for the GUI tests of the STOP (the MC200 V2 simulator).
#include "../shell/shell_fixture.h"

#include "ui/mc1/mc1_axes_page.h"
#include "ui/mc1/mc1_axis_parameters_box.h"

#include <QFile>
#include <QLabel>
#include <QPushButton>
#include <QTemporaryDir>

namespace cambench::test {

// The controller's own parameter table loaded as a technician loads it (a
// CSV file): the simulator's numbers (its default --parameter-base 0x1000).
// What an axis does, read through CamBench's guess, is no fact: a STOP
// test that checks "nothing moves" reads through the controller's table.
inline bool loadTheControllersTable(Mc1AxesPage* axes) {
    if (!axes->parametersBox()->table().provisional) return true;
    static QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("mc200-parameters.csv"));
    QByteArray csv = "name,axis,parameter\n";
    const char* names[] = {"position", "target", "status"};
    for (int axis = 1; axis <= 8; ++axis)
        for (int i = 0; i < 3; ++i)
            csv += QByteArray(names[i]) + ',' + QByteArray::number(axis) + ",0x" +
                   QByteArray::number(0x1000 + 0x10 * axis + i, 16) + '\n';
    QFile file(path);
    return dir.isValid() && file.open(QIODevice::WriteOnly) && file.write(csv) == csv.size() &&
           (file.close(), axes->parametersBox()->load(path));
}

// The axis shown on `axes` jogs + (the controller's table loaded, Jog +
// clicked and confirmed as a person does, the page shown in `window`); true
// once the page says so.
inline bool jogPlus(MainWindow* window, Mc1AxesPage* axes) {
    if (!loadTheControllersTable(axes)) return false;
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
