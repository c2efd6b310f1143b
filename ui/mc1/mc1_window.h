#pragma once

#include "mc1_page.h"

#include "model/device_identity.h"
#include "model/mc1/mc1_backup_file.h"
#include "ui/device_facts.h"

namespace cambench {

class Mc1AxesPage;
class Mc1Gui;
class Mc1MemoryPage;
class Mc1PointsPage;
class Mc1ProgramPage;
class Mc1TrendPage;
class Mc1VariablesPage;

// The MC-1 family's part of the main window: Variables, Flags & I/O,
// Program, Axes, Memory and Trend; backup, verify and restore in the Device
// menu; the controller identified when it comes on the line (the shown
// page's polls and the line's loss: LiveFamilyWindow).
class Mc1Window : public FactsWindow<Mc1Facts> {
    Q_OBJECT
public:
    Mc1Window(Mc1Gui* gui, MainWindow* window);

    void addMenuEntries(const FamilyMenus& menus) override;
    void deviceOnLine(bool load) override;
    QList<TourVisit> tourVisits() const override;
    QList<TourStop> tourStops(const TourVisit& visit, const QString& directory) override;

    Mc1VariablesPage* variablesPage() const { return m_variables; }
    Mc1PointsPage* pointsPage() const { return m_points; }
    Mc1ProgramPage* programPage() const { return m_program; }
    Mc1AxesPage* axesPage() const { return m_axes; }
    Mc1MemoryPage* memoryPage() const { return m_memory; }
    Mc1TrendPage* trendPage() const { return m_trend; }

    // Device menu: the use cases of comm/mc1/usecases with file dialogs.
    void backupToFile(const QString& path);
    void verifyFile(const QString& path);
    // Asks first when another controller answers than the file's
    // (askRestoreTarget), then whether to restore.
    void restoreFile(const QString& path);

private:
    void restoreTo(const QString& path, const Mc1Backup& backup, const ReplacementConsent& consent);

    Mc1Gui* m_mc1;
    Mc1VariablesPage* m_variables;
    Mc1PointsPage* m_points;
    Mc1ProgramPage* m_program;
    Mc1AxesPage* m_axes;
    Mc1MemoryPage* m_memory;
    Mc1TrendPage* m_trend;
};

// The MC-1 part of `window` (tests, the tour); nullptr when it has none.
Mc1Window* mc1Window(const MainWindow* window);

}  // namespace cambench
