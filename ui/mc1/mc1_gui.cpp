#include "mc1_gui.h"

#include "mc1_settings.h"
#include "mc1_watch_model.h"
#include "mc1_window.h"

namespace cambench {

Mc1Gui::Mc1Gui(DeviceSession* session, QObject* parent)
    : FamilyGui(QStringLiteral("mc1"), session, parent), m_watch(new Mc1WatchModel(this)) {
    if (const std::optional<Mc1Project> kept = mc1settings::loadWatchList())
        m_watch->restore(*kept);  // the last session's list and names, not read yet
    else
        m_watch->addRange(1, 10);  // a first look at the controller's variables
    connect(m_watch, &Mc1WatchModel::listChanged, this,
            [this] { mc1settings::saveWatchList(m_watch->toProject(QStringLiteral("auto"))); });
}

FamilyWindow* Mc1Gui::createWindow(MainWindow* window) {
    return new Mc1Window(this, window);
}

}  // namespace cambench
