#include "compax3_gui.h"

#include "compax3_object_model.h"
#include "compax3_window.h"

#include "comm/compax3/compax3_device.h"
#include "comm/compax3/compax3_objects.h"
#include "model/compax3/compax3_family_id.h"
#include "ui/device_session.h"

namespace cambench {

Compax3Gui::Compax3Gui(DeviceSession* session, QObject* parent)
    : FamilyGui(compax3FamilyId, session, parent),
      m_dictionary(Compax3Dictionary::builtin()),
      m_objects(new Compax3ObjectModel(this)),
      // A first look: where the axis is.
      m_watch({comm::kCompax3Position}) {
    m_objects->setDictionary(m_dictionary);
    // The machine list, the title and the quit question count them.
    connect(m_objects, &Compax3ObjectModel::editsChanged, this, &FamilyGui::titleChanged);
}

int Compax3Gui::unwrittenCount() const {
    return int(m_objects->edits().size());
}

void Compax3Gui::readForReport(QWidget* parent, std::function<void(const Status&)> done) {
    Q_UNUSED(parent);
    Compax3Report::read(session(), this, m_dictionary,
                        [this, done](Result<Compax3ReportReading> reading) {
                            // Never the last drive's values as this one's.
                            m_report.reset();
                            if (reading) m_report = *reading;
                            done(reading ? success() : Status(reading.error()));
                        });
}

QString Compax3Gui::reportSection(QTextDocument& document, const QString& resourcePrefix) const {
    Q_UNUSED(document);
    Q_UNUSED(resourcePrefix);
    QString html;
    // Typed in on this PC and not on the drive: named, as the CamCon's
    // report marks its edits.
    if (const int edits = unwrittenCount(); edits > 0)
        html += QStringLiteral("<p><b>%1</b></p>")
                    .arg(tr("%n value(s) typed in on this PC are NOT on the drive; the values "
                            "below are the drive's.",
                            nullptr, edits)
                             .toHtmlEscaped());
    return html + Compax3Report::html(m_report, m_dictionary);
}

void Compax3Gui::setDictionary(const Compax3Dictionary& dictionary) {
    m_dictionary = dictionary;
    m_objects->setDictionary(dictionary);
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
