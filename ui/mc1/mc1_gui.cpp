#include "mc1_gui.h"

#include "mc1_watch_model.h"
#include "mc1_window.h"

namespace cambench {

Mc1Gui::Mc1Gui(DeviceSession* session, QObject* parent)
    : FamilyGui(QStringLiteral("mc1"), session, parent), m_watch(new Mc1WatchModel(this)) {
    m_watch->addRange(1, 10);  // a first look at the controller's variables
}

FamilyWindow* Mc1Gui::createWindow(MainWindow* window) {
    return new Mc1Window(this, window);
}

}  // namespace cambench
