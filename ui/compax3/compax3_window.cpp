#include "compax3_window.h"

#include "compax3_gui.h"
#include "compax3_motion_page.h"
#include "compax3_object_model.h"
#include "compax3_objects_page.h"
#include "compax3_parameters_page.h"
#include "compax3_status_page.h"
#include "compax3_watch_page.h"

#include "ui/device_session.h"
#include "ui/live_poll_cycle.h"
#include "ui/main_window.h"
#include "ui/sentence.h"

#include <QMessageBox>
#include <QPushButton>

namespace cambench {

namespace {
constexpr int kPollMs = 500;
}  // namespace

Compax3Window::Compax3Window(Compax3Gui* gui, MainWindow* window)
    : FamilyWindow(gui, window),
      m_compax3(gui),
      m_objects(new Compax3ObjectsPage(gui->session(), gui)),
      m_status(new Compax3StatusPage(gui->session())),
      m_motion(new Compax3MotionPage(gui->session())),
      m_watch(new Compax3WatchPage(gui->session(), gui)),
      m_parameters(new Compax3ParametersPage(gui->session(), gui)),
      m_poll(new LivePollCycle(gui->session(), kPollMs, this)) {
    // Polls go on all the time a page is shown: not a job for the progress bar.
    for (const QString& title :
         {Compax3Page::tr("Read drive status"), Compax3WatchPage::tr("Read watched objects")})
        window->addQuietJobTitle(title);
    // One copy of each drive value: what one page wrote, the Objects page
    // reads again and shows as the drive's.
    for (Compax3Page* page : compax3Pages())
        connect(page, &Compax3Page::objectsWritten, m_objects,
                [this](const QList<Compax3ObjectId>& ids) { m_objects->read(ids); });
    connect(gui->session(), &DeviceSession::stateChanged, this, [this] {
        if (m_compax3->session()->isOnline()) return;
        // The line is gone: what the pages show is no longer known to be true.
        for (Compax3Page* page : compax3Pages()) page->lineLost();
    });
}

QList<Compax3Page*> Compax3Window::compax3Pages() const {
    return {m_objects, m_status, m_motion, m_watch, m_parameters};
}

QList<SectionPage*> Compax3Window::pages() const {
    QList<SectionPage*> pages;
    for (Compax3Page* page : compax3Pages()) pages << page;
    return pages;
}

void Compax3Window::setFacts(const Compax3Facts& facts) {
    m_facts = facts;
    for (Compax3Page* page : compax3Pages()) page->setFacts(facts);
}

void Compax3Window::forgetDevice() {
    FamilyWindow::forgetDevice();
    setFacts({});
}

void Compax3Window::deviceOnLine(bool load) {
    // The shell had every family forget the device before (forgetDevice).
    m_compax3->session()->setDeviceChecked(false);
    m_compax3->session()->run<comm::Compax3Device, Compax3Identity>(
        this, tr("Identify drive"),
        // The dictionary in use words its refusals from the first request.
        [dictionary = m_compax3->dictionary()](comm::Compax3Device& device, comm::JobContext&) {
            device.setDictionary(dictionary);
            return device.identity();
        },
        [this, load](Result<Compax3Identity> identity) {
            QString line;
            if (identity) {
                line = tr("%1, serial number %2").arg(identity->info, identity->serial);
                m_compax3->setIdentity(line);
                m_compax3->session()->setDeviceChecked(true);
                setFacts({true, *identity});
            }
            window()->showMessage(identity ? tr("Connected: %1").arg(line)
                                           : tr("No Compax3 identified itself: %1")
                                                 .arg(asSentence(identity.error().message)));
            if (load) window()->reportLoaded(identity.ok());
            if (m_shown) m_shown->poll();
        });
}

void Compax3Window::pageShown(SectionPage* page) {
    m_shown = nullptr;
    for (Compax3Page* mine : compax3Pages())
        if (mine == page) m_shown = mine;
    // A missed cycle makes the shown page's values stale, a cycle spent
    // behind a long job (a backup) pauses them: the shell's poll cycle.
    m_poll->setShown(m_shown);
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
