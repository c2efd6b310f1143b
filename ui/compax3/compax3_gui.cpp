#include "compax3_gui.h"

#include "compax3_window.h"

#include "comm/compax3/compax3_device.h"
#include "comm/compax3/compax3_objects.h"
#include "ui/device_session.h"

namespace cambench {

Compax3Gui::Compax3Gui(DeviceSession* session, QObject* parent)
    : FamilyGui(QStringLiteral("compax3"), session, parent),
      m_dictionary(Compax3Dictionary::builtin()),
      // A first look: where the axis is.
      m_watch({comm::kCompax3Position}) {}

void Compax3Gui::setDictionary(const Compax3Dictionary& dictionary) {
    m_dictionary = dictionary;
    // The drive's refusals are worded, and *Check this device…* tries the
    // objects, by the dictionary in use (a drive of another family: no-op).
    session()->run<comm::Compax3Device, bool>(
        this, tr("Use dictionary"),
        [dictionary](comm::Compax3Device& device, comm::JobContext&) -> Result<bool> {
            device.setDictionary(dictionary);
            return true;
        },
        [](Result<bool>) {});
    Q_EMIT dictionaryChanged();
}

FamilyWindow* Compax3Gui::createWindow(MainWindow* window) {
    return new Compax3Window(this, window);
}

}  // namespace cambench
