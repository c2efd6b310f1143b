#pragma once

#include "ui/live_device_page.h"

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

Q_SIGNALS:
    // This page changed these objects on the drive: the pages that show
    // them read them again, so that every page shows the drive's value.
    void objectsWritten(const QList<cambench::Compax3ObjectId>& ids);

protected:
    virtual void factsChanged() {}
    // One poll of the drive's status on the shell's poll cycle (runPoll: a
    // poll already waiting is not queued twice); `show` gets what was read.
    bool pollStatus(std::function<void(const comm::Compax3DriveStatus&)> show);

private:
    Compax3Facts m_facts;
};

}  // namespace cambench
