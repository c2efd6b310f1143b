#include "live_family_window.h"

#include "device_session.h"
#include "live_device_page.h"
#include "live_poll_cycle.h"
#include "main_window.h"
#include "sentence.h"

namespace cambench {

namespace {
constexpr int kPollMs = 500;
}  // namespace

LiveFamilyWindow::LiveFamilyWindow(FamilyGui* gui, MainWindow* window,
                                   const QStringList& pollTitles)
    : FamilyWindow(gui, window), m_poll(new LivePollCycle(gui->session(), kPollMs, this)) {
    for (const QString& title : pollTitles) window->addQuietJobTitle(title);
    connect(gui->session(), &DeviceSession::stateChanged, this, [this] {
        if (this->gui()->session()->isOnline()) return;
        // The line is gone: what the pages show is no longer known to be true.
        for (LiveDevicePage* page : m_pages) page->lineLost();
    });
}

void LiveFamilyWindow::setLivePages(const QList<LiveDevicePage*>& pages) {
    m_pages = pages;
}

QList<SectionPage*> LiveFamilyWindow::pages() const {
    QList<SectionPage*> pages;
    for (LiveDevicePage* page : m_pages) pages << page;
    return pages;
}

void LiveFamilyWindow::pageShown(SectionPage* page) {
    m_shown = nullptr;
    for (LiveDevicePage* mine : m_pages)
        if (mine == page) m_shown = mine;
    // A page drawn from another page's values (a trend) has that page
    // polled; a missed cycle makes the values stale, a cycle spent behind
    // a long job (a backup) pauses them: the shell's poll cycle.
    m_poll->setShown(m_shown ? m_shown->polledPage() : nullptr);
}

void LiveFamilyWindow::identifying() {
    // The shell had every family forget the device before (forgetDevice).
    gui()->session()->setDeviceChecked(false);
}

void LiveFamilyWindow::identified(bool load, const Result<QString>& identity,
                                  const QString& nobody) {
    if (identity) {
        gui()->setIdentity(*identity);
        gui()->session()->setDeviceChecked(true);
    } else if (identity.error().kind != ErrorKind::Cancelled) {
        gui()->session()->setIdentifyFailed(identity.error().message);
    }
    window()->showMessage(identity ? tr("Connected: %1").arg(*identity)
                                   : nobody.arg(asSentence(identity.error().message)));
    if (load) window()->reportLoaded(identity.ok());
    if (m_shown) m_shown->poll();
}

}  // namespace cambench
