#pragma once

#include "ui/live_device_page.h"
#include "ui/live_freshness.h"

#include "comm/compax3/compax3_device.h"

#include <functional>

namespace cambench {

// What the window knows of the connected drive once it identified itself;
// `known` false while nothing (or another device) is on the line.
struct Compax3Facts {
    bool known = false;
    Compax3Identity identity;
};

// A page of the Compax3 family: told which drive is connected, polled while
// shown, able to ask before it acts.
class Compax3Page : public LiveDevicePage {
    Q_OBJECT
public:
    using LiveDevicePage::LiveDevicePage;

    const Compax3Facts& facts() const { return m_facts; }
    void setFacts(const Compax3Facts& facts) {
        m_facts = facts;
        factsChanged();
    }

    // The live values' freshness changed: a page greys what it shows with
    // `text` ("No answer since 12:03:04", "Paused") unless `state` is Live.
    virtual void showFreshness(LiveFreshness::State state, const QString& text) {
        Q_UNUSED(state);
        Q_UNUSED(text);
    }

Q_SIGNALS:
    // This page changed these objects on the drive: the pages that show
    // them read them again, so that every page shows the drive's value.
    void objectsWritten(const QList<cambench::Compax3ObjectId>& ids);

protected:
    virtual void factsChanged() {}
    // One poll of the drive's status (a Poll job; a poll already waiting is
    // not queued twice); `show` gets what was read.
    bool pollStatus(std::function<void(const comm::Compax3DriveStatus&)> show);

private:
    Compax3Facts m_facts;
};

}  // namespace cambench
