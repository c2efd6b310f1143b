#pragma once

#include "compax3_page.h"

#include "ui/family_gui.h"

namespace cambench {

class LivePollCycle;
class Compax3Gui;
class Compax3MotionPage;
class Compax3ObjectsPage;
class Compax3ParametersPage;
class Compax3StatusPage;
class Compax3WatchPage;

// The Compax3 family's part of the main window: Objects, Status, Motion,
// Watch and Parameters; the drive identified when it comes on the line,
// the shown page's live values polled, everything marked stale when the
// line goes.
class Compax3Window : public FamilyWindow {
    Q_OBJECT
public:
    Compax3Window(Compax3Gui* gui, MainWindow* window);

    QList<SectionPage*> pages() const override;
    void deviceOnLine(bool load) override;
    // Also the facts (variant, type) the pages act on.
    void forgetDevice() override;
    void pageShown(SectionPage* page) override;
    bool confirmClose() override;
    QList<TourVisit> tourVisits() const override;
    QList<TourStop> tourStops(const TourVisit& visit, const QString& directory) override;

    const Compax3Facts& facts() const { return m_facts; }
    Compax3ObjectsPage* objectsPage() const { return m_objects; }
    Compax3StatusPage* statusPage() const { return m_status; }
    Compax3MotionPage* motionPage() const { return m_motion; }
    Compax3WatchPage* watchPage() const { return m_watch; }
    Compax3ParametersPage* parametersPage() const { return m_parameters; }
    // The shown page's polls and their freshness (tests drive its cycles).
    LivePollCycle* pollCycle() const { return m_poll; }

private:
    void setFacts(const Compax3Facts& facts);
    QList<Compax3Page*> compax3Pages() const;

    Compax3Gui* m_compax3;
    Compax3ObjectsPage* m_objects;
    Compax3StatusPage* m_status;
    Compax3MotionPage* m_motion;
    Compax3WatchPage* m_watch;
    Compax3ParametersPage* m_parameters;
    Compax3Facts m_facts;
    Compax3Page* m_shown = nullptr;
    LivePollCycle* m_poll;
};

// The Compax3 part of `window` (tests, the tour); nullptr when it has none.
Compax3Window* compax3Window(const MainWindow* window);

}  // namespace cambench
