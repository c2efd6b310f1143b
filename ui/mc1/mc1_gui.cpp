#include "mc1_gui.h"

#include "mc1_settings.h"
#include "mc1_watch_model.h"
#include "mc1_window.h"
#include "model/mc1/mc1_family_id.h"

namespace cambench {

Mc1Gui::Mc1Gui(DeviceSession* session, QObject* parent)
    : FamilyGui(mc1FamilyId, session, parent), m_watch(new Mc1WatchModel(this)) {
    if (const std::optional<Mc1Project> kept = mc1settings::loadWatchList())
        m_watch->restore(*kept);  // the last session's list and names, not read yet
    else
        m_watch->addRange(1, 10);  // a first look at the controller's variables
    connect(m_watch, &Mc1WatchModel::listChanged, this,
            [this] { mc1settings::saveWatchList(m_watch->toProject(QStringLiteral("auto"))); });
}

void Mc1Gui::readForReport(QWidget* parent, std::function<void(const Status&)> done) {
    Q_UNUSED(parent);
    Mc1Report::read(session(), this, [this, done](Result<Mc1ReportReading> reading) {
        // A report never shows the last device's values as this one's.
        m_report.reset();
        if (reading) m_report = *reading;
        done(reading ? success() : Status(reading.error()));
    });
}

QString Mc1Gui::reportSection(QTextDocument& document, const QString& resourcePrefix) const {
    Q_UNUSED(document);
    Q_UNUSED(resourcePrefix);
    return Mc1Report::html(m_report);
}

FamilyWindow* Mc1Gui::createWindow(MainWindow* window) {
    return new Mc1Window(this, window);
}

}  // namespace cambench
