#pragma once

#include "compax3_page.h"

#include "ui/device_facts.h"

namespace cambench {

class Compax3Gui;
class Compax3MotionPage;
class Compax3ObjectsPage;
class Compax3ParametersPage;
class Compax3StatusPage;
class Compax3WatchPage;

// The Compax3 family's part of the main window: Objects, Status, Motion,
// Watch and Parameters; the drive identified when it comes on the line
// (the shown page's polls and the line's loss: LiveFamilyWindow).
class Compax3Window : public FactsWindow<Compax3Facts> {
    Q_OBJECT
public:
    Compax3Window(Compax3Gui* gui, MainWindow* window);

    void deviceOnLine(bool load) override;
    bool confirmClose() override;
    QList<TourVisit> tourVisits() const override;
    QList<TourStop> tourStops(const TourVisit& visit, const QString& directory) override;

    Compax3ObjectsPage* objectsPage() const { return m_objects; }
    Compax3StatusPage* statusPage() const { return m_status; }
    Compax3MotionPage* motionPage() const { return m_motion; }
    Compax3WatchPage* watchPage() const { return m_watch; }
    Compax3ParametersPage* parametersPage() const { return m_parameters; }

private:
    QList<Compax3Page*> compax3Pages() const;

    Compax3Gui* m_compax3;
    Compax3ObjectsPage* m_objects;
    Compax3StatusPage* m_status;
    Compax3MotionPage* m_motion;
    Compax3WatchPage* m_watch;
    Compax3ParametersPage* m_parameters;
};

// The Compax3 part of `window` (tests, the tour); nullptr when it has none.
Compax3Window* compax3Window(const MainWindow* window);

}  // namespace cambench
