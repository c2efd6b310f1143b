#pragma once

#include "ui/section_page.h"

#include "comm/mc1/mc1_device.h"

#include <QSet>

class QLabel;

namespace cambench {

class DeviceSession;

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
class Mc1Page : public SectionPage {
    Q_OBJECT
public:
    explicit Mc1Page(DeviceSession* session, QWidget* parent = nullptr)
        : SectionPage(parent), m_session(session) {}

    DeviceSession* session() const { return m_session; }
    const Mc1Facts& facts() const { return m_facts; }
    void setFacts(const Mc1Facts& facts) {
        m_facts = facts;
        factsChanged();
    }
    // One poll of the live values the page shows; false: it has none.
    virtual bool poll() { return false; }
    // The line went away or another device came: shown values go stale.
    virtual void markStale() {}

protected:
    virtual void factsChanged() {}
    // "Write V12 = 5 to the MC200 V2?" with `detail` below; true on Yes.
    bool confirm(const QString& title, const QString& question, const QString& detail = {});
    // A live-value poll came back: tells the session's freshness.
    void pollAnswered(bool ok);
    // The line under the page that says what the last action did.
    QLabel* resultLine();
    void showResult(const QString& text, bool ok);

private:
    DeviceSession* m_session;
    Mc1Facts m_facts;
    QLabel* m_result = nullptr;
};

}  // namespace cambench
