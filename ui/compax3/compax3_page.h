#pragma once

#include "ui/device_facts.h"

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
class Compax3Page : public FactsPage<Compax3Facts> {
    Q_OBJECT
public:
    using FactsPage::FactsPage;

Q_SIGNALS:
    // This page changed these objects on the drive: the pages that show
    // them read them again, so that every page shows the drive's value.
    void objectsWritten(const QList<cambench::Compax3ObjectId>& ids);

protected:
    // One poll of the drive's status on the shell's poll cycle (runPoll: a
    // poll already waiting is not queued twice); `show` gets what was read.
    bool pollStatus(std::function<void(const comm::Compax3DriveStatus&)> show);
};

}  // namespace cambench
