#pragma once

#include "section_page.h"

class QLabel;

namespace cambench {

class DeviceSession;

// A page that shows a device's live values and acts on the device (the
// MC-1's and the Compax3's pages): polled while shown, marked stale when
// the line goes, asks before it acts, and says under itself what the last
// action did.
class LiveDevicePage : public SectionPage {
    Q_OBJECT
public:
    explicit LiveDevicePage(DeviceSession* session, QWidget* parent = nullptr)
        : SectionPage(parent), m_session(session) {}

    DeviceSession* session() const { return m_session; }
    // One poll of the live values the page shows; false: it has none.
    virtual bool poll() { return false; }
    // The line went away or another device came: shown values go stale.
    virtual void markStale() {}
    // Another device came (or another family's): what the last action did
    // was done to the device before, and is no longer said.
    void clearResult();

protected:
    // A warning box: `question` with `detail` below, Cancel the default; a
    // button named `title` confirms. True on that button.
    bool confirm(const QString& title, const QString& question, const QString& detail = {});
    // A live-value poll came back: tells the session's freshness.
    void pollAnswered(bool ok);
    // The line under the page that says what the last action did
    // ("pageResult").
    QLabel* resultLine();
    void showResult(const QString& text, bool ok);

private:
    DeviceSession* m_session;
    QLabel* m_result = nullptr;
};

}  // namespace cambench
