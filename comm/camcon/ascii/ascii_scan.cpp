#include "ascii_camcon.h"

#include <QCoreApplication>
#include "ascii_support.h"

namespace cambench::comm {

namespace {

// Puts the link's destination, timeout and retries back however the scan ends.
class LinkSettingsGuard {
public:
    explicit LinkSettingsGuard(AsciiLink& link) : m_link(link), m_saved(link.settings()) {}
    ~LinkSettingsGuard() {
        m_link.setDevice(m_saved.device);
        m_link.setTimeout(m_saved.timeoutMs);
        m_link.setRetries(m_saved.retries);
    }
    LinkSettingsGuard(const LinkSettingsGuard&) = delete;
    LinkSettingsGuard& operator=(const LinkSettingsGuard&) = delete;

private:
    AsciiLink& m_link;
    AsciiSettings m_saved;
};

}  // namespace

Result<QList<int>> AsciiCamCon::scanBus(int first, int last, int timeoutMs,
                                        const ProgressFn& progress) {
    if (m_link.settings().framing != Framing::Multiuser) {
        return Error::usage(QCoreApplication::translate(
            "cambench::comm",
            "a bus scan needs the Multiuser protocol; connect with --protocol multiuser"));
    }
    first = qBound(0, first, 63);
    last = qBound(first, last, 63);
    const LinkSettingsGuard guard(m_link);
    // An absent device never answers: one short attempt per number.
    m_link.setTimeout(timeoutMs);
    m_link.setRetries(0);
    QList<int> found;
    for (int device = first; device <= last; ++device) {
        if (progress) progress(device - first, last - first + 1);
        m_link.setDevice(device);
        const Result<Fields> reply = m_link.call('?', "UNIT");
        if (reply) {
            found.append(device);
            continue;
        }
        switch (reply.error().kind) {
            case ErrorKind::Communication:
                break;  // nobody there
            case ErrorKind::Cancelled:
                return reply.error();
            default:
                found.append(device);
                break;  // it answered, if with an error
        }
    }
    if (progress) progress(last - first + 1, last - first + 1);
    return found;
}

Result<QList<int>> AsciiCamCon::scanBus(int first, int last, const ProgressFn& progress) {
    return scanBus(first, last, 0, progress);
}

}  // namespace cambench::comm
