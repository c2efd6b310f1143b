#include "compax3_window.h"

#include "compax3_gui.h"
#include "compax3_motion_page.h"
#include "compax3_object_model.h"
#include "compax3_objects_page.h"
#include "compax3_parameters_page.h"
#include "compax3_status_page.h"
#include "compax3_watch_page.h"

#include "ui/device_session.h"
#include "ui/main_window.h"

#include <QMessageBox>
#include <QPushButton>

namespace cambench {

Compax3Window::Compax3Window(Compax3Gui* gui, MainWindow* window)
    : FactsWindow(
          gui, window,
          {Compax3Page::tr("Read drive status"), Compax3WatchPage::tr("Read watched objects")}),
      m_compax3(gui),
      m_objects(new Compax3ObjectsPage(gui->session(), gui)),
      m_status(new Compax3StatusPage(gui->session())),
      m_motion(new Compax3MotionPage(gui->session())),
      m_watch(new Compax3WatchPage(gui->session(), gui)),
      m_parameters(new Compax3ParametersPage(gui->session(), gui)) {
    setFactsPages({m_objects, m_status, m_motion, m_watch, m_parameters});
    // One copy of each drive value: what one page wrote, the Objects page
    // reads again and shows as the drive's.
    for (Compax3Page* page : compax3Pages())
        connect(page, &Compax3Page::objectsWritten, m_objects,
                [this](const QList<Compax3ObjectId>& ids) { m_objects->read(ids); });
}

QList<Compax3Page*> Compax3Window::compax3Pages() const {
    return {m_objects, m_status, m_motion, m_watch, m_parameters};
}

void Compax3Window::deviceOnLine(bool load) {
    identifying();
    m_compax3->session()->run<comm::Compax3Device, Compax3Identity>(
        this, tr("Identify drive"),
        // The dictionary in use words its refusals from the first request.
        [dictionary = m_compax3->dictionary()](comm::Compax3Device& device, comm::JobContext&) {
            device.setDictionary(dictionary);
            return device.identity();
        },
        [this, load](Result<Compax3Identity> identity) {
            if (identity) setFacts({true, *identity});
            identified(load,
                       identity
                           ? Result<QString>(
                                 tr("%1, serial number %2").arg(identity->info, identity->serial))
                           : identity.error(),
                       tr("No Compax3 identified itself: %1"));
        });
}

bool Compax3Window::confirmClose() {
    const int edits = int(m_objects->model()->edits().size());
    if (edits == 0) return true;
    QMessageBox ask(
        QMessageBox::Warning, tr("Unwritten values"),
        tr("%n value(s) typed in on the Objects page are not on the drive.", nullptr, edits),
        QMessageBox::Cancel, window());
    ask.setInformativeText(tr("Closing drops them."));
    QPushButton* close = ask.addButton(tr("Close and drop them"), QMessageBox::DestructiveRole);
    ask.setDefaultButton(QMessageBox::Cancel);
    ask.exec();
    return ask.clickedButton() == close;
}

Compax3Window* compax3Window(const MainWindow* window) {
    return window ? window->findChild<Compax3Window*>() : nullptr;
}

}  // namespace cambench
