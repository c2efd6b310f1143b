#pragma once

#include "live_device_page.h"
#include "live_family_window.h"

namespace cambench {

// What a live family's window knows of the connected device once it
// identified itself - its facts: a family's own struct (the MC-1's variant
// and capabilities, the Compax3's identity) whose `known` is false while
// nothing (or another device) is on the line. The window holds them and
// tells each of its pages; the pages act on them (factsChanged).

template <class Facts>
class FactsPage : public LiveDevicePage {
public:
    using LiveDevicePage::LiveDevicePage;

    const Facts& facts() const { return m_facts; }
    void setFacts(const Facts& facts) {
        m_facts = facts;
        factsChanged();
    }

protected:
    virtual void factsChanged() {}

private:
    Facts m_facts;
};

// The window of such pages: every page of it is a FactsPage<Facts>.
template <class Facts>
class FactsWindow : public LiveFamilyWindow {
public:
    using LiveFamilyWindow::LiveFamilyWindow;

    const Facts& facts() const { return m_facts; }
    // Also the facts the pages act on.
    void forgetDevice() override {
        LiveFamilyWindow::forgetDevice();
        setFacts({});
    }

protected:
    void setFacts(const Facts& facts) {
        m_facts = facts;
        for (LiveDevicePage* page : livePages())
            static_cast<FactsPage<Facts>*>(page)->setFacts(facts);
    }
    void setFactsPages(const QList<FactsPage<Facts>*>& pages) {
        setLivePages(QList<LiveDevicePage*>(pages.cbegin(), pages.cend()));
    }

private:
    Facts m_facts;
};

}  // namespace cambench
