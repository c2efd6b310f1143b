#pragma once

#include "ui/device_facts.h"
#include "ui/sentence.h"

#include "comm/mc1/mc1_device.h"

#include <QSet>

namespace cambench {

// What the window knows of the connected MC100/MC200 once it identified
// itself; `known` false while nothing (or another device) is on the line.
struct Mc1Facts {
    bool known = false;
    comm::Mc1Variant variant = comm::Mc1Variant::Mc200V2;
    QString source;  // "probed", "as given (...)"
    QSet<comm::Mc1Capability> capabilities;
    bool has(comm::Mc1Capability capability) const { return capabilities.contains(capability); }
};

// A page of the MC-1 family: told what the controller is, polled while
// shown (live values), and able to ask before it acts.
class Mc1Page : public FactsPage<Mc1Facts> {
    Q_OBJECT
public:
    using FactsPage::FactsPage;

protected:
    // The outcome of an acting command for a person: a failure (the page's
    // values go stale), or done - the controller acknowledged it - with,
    // apart, why reading back failed. The state read back, when there is one.
    template <class T>
    const T* acknowledged(const Result<comm::Mc1Done<T>>& done, const QString& what) {
        if (!done) {
            showResult(asSentence(done.error().message), false);
            // What the device does now is not known: the values shown grey.
            freshness()->missed();
            markStale();
            return nullptr;
        }
        if (!done->after) {
            freshness()->missed();
            markStale();
            showResult(tr("Done: %1 (the controller acknowledged it). Reading back failed: %2")
                           .arg(capitalised(what), done->readBackProblem),
                       true);
            return nullptr;
        }
        return &*done->after;
    }
};

}  // namespace cambench
