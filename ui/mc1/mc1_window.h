#pragma once

#include "mc1_page.h"

#include "ui/family_gui.h"

namespace cambench {

class LivePollCycle;
class Mc1AxesPage;
class Mc1Gui;
class Mc1MemoryPage;
class Mc1PointsPage;
class Mc1ProgramPage;
class Mc1TrendPage;
class Mc1VariablesPage;

// The MC-1 family's part of the main window: Variables, Flags & I/O,
// Program, Axes, Memory and Trend; backup, verify and restore in the Device
// menu; the controller identified when it comes on the line, and the
// shown page's live values polled.
class Mc1Window : public FamilyWindow {
    Q_OBJECT
public:
    Mc1Window(Mc1Gui* gui, MainWindow* window);

    QList<SectionPage*> pages() const override;
    void addMenuEntries(const FamilyMenus& menus) override;
    void deviceOnLine(bool load) override;
    // Also the facts (variant, type) the pages act on.
    void forgetDevice() override;
    void pageShown(SectionPage* page) override;
    QList<TourVisit> tourVisits() const override;
    QList<TourStop> tourStops(const TourVisit& visit, const QString& directory) override;

    const Mc1Facts& facts() const { return m_facts; }
    Mc1VariablesPage* variablesPage() const { return m_variables; }
    Mc1PointsPage* pointsPage() const { return m_points; }
    Mc1ProgramPage* programPage() const { return m_program; }
    Mc1AxesPage* axesPage() const { return m_axes; }
    Mc1MemoryPage* memoryPage() const { return m_memory; }
    Mc1TrendPage* trendPage() const { return m_trend; }
    // The shown page's poll cycle (tests drive it cycle by cycle).
    LivePollCycle* pollCycle() const { return m_poll; }

    // Device menu: the use cases of comm/mc1/usecases with file dialogs.
    void backupToFile(const QString& path);
    void verifyFile(const QString& path);
    void restoreFile(const QString& path);

private:
    void setFacts(const Mc1Facts& facts);
    QList<Mc1Page*> mc1Pages() const;

    Mc1Gui* m_mc1;
    Mc1VariablesPage* m_variables;
    Mc1PointsPage* m_points;
    Mc1ProgramPage* m_program;
    Mc1AxesPage* m_axes;
    Mc1MemoryPage* m_memory;
    Mc1TrendPage* m_trend;
    Mc1Facts m_facts;
    Mc1Page* m_shown = nullptr;
    LivePollCycle* m_poll;
};

// The MC-1 part of `window` (tests, the tour); nullptr when it has none.
Mc1Window* mc1Window(const MainWindow* window);

}  // namespace cambench
