#pragma once

#include "family_gui.h"

#include "model/result.h"

#include <QStringList>

namespace cambench {

class LiveDevicePage;
class LivePollCycle;

// A family window whose pages show a device's live values and act on it
// (LiveDevicePage: the MC-1's and the Compax3's): the shown page polled on
// the shell's poll cycle, every page's values stale when the line goes,
// the polls kept off the progress bar, and the device's identification
// said the same way. What the family knows of its device (its facts), how
// it identifies it, its menus and its tour stay in the family.
class LiveFamilyWindow : public FamilyWindow {
    Q_OBJECT
public:
    // `pollTitles`: the titles of the pages' poll jobs, which run all the
    // time a page is shown (not jobs for the progress bar).
    LiveFamilyWindow(FamilyGui* gui, MainWindow* window, const QStringList& pollTitles);

    QList<SectionPage*> pages() const override;
    void pageShown(SectionPage* page) override;
    // The shown page's polls and their freshness (tests drive its cycles).
    LivePollCycle* pollCycle() const { return m_poll; }

protected:
    // The family's pages in the window's order; once, from its constructor.
    void setLivePages(const QList<LiveDevicePage*>& pages);
    const QList<LiveDevicePage*>& livePages() const { return m_pages; }
    // The page shown now, when it is one of this family's.
    LiveDevicePage* shownPage() const { return m_shown; }

    // deviceOnLine() begins: nothing is checked until identified() says so.
    void identifying();
    // The device answered deviceOnLine()'s identification with `identity`
    // (the line the connection strip shows) or did not (`nobody`, %1: why):
    // said in the window, the start reported when `load`, the shown page
    // polled. The family has taken its facts before.
    void identified(bool load, const Result<QString>& identity, const QString& nobody);

private:
    QList<LiveDevicePage*> m_pages;
    LiveDevicePage* m_shown = nullptr;
    LivePollCycle* m_poll;
};

}  // namespace cambench
