#include "ascii_camcon.h"

#include <QCoreApplication>
#include "ascii_support.h"

#include <QElapsedTimer>
#include <QSet>

#include <algorithm>
#include <utility>

namespace cambench::comm {

namespace {

// How long a number gets to start answering in the quick looks. The
// simulator answers after ~2 ms, a CamCon after a few. A device that is
// slower still is not missed: its answer, whenever it comes, names it in
// its Multiuser header (below), and on a real bus where it collides with
// the next request the damaged bytes send the numbers asked just before to
// a patient last look.
constexpr int kQuickTurnaroundMs = 5;

// Puts the link's destination, timeout and retries back however the scan
// ends, and stops listening.
class ScanGuard {
public:
    explicit ScanGuard(AsciiLink& link) : m_link(link), m_saved(link.settings()) {}
    ~ScanGuard() {
        m_link.engine().setIncomingObserver({});
        m_link.setDevice(m_saved.device);
        m_link.setTimeout(m_saved.timeoutMs);
        m_link.setRetries(m_saved.retries);
    }
    ScanGuard(const ScanGuard&) = delete;
    ScanGuard& operator=(const ScanGuard&) = delete;

private:
    AsciiLink& m_link;
    AsciiSettings m_saved;
};

// Every frame heard during a scan. Each number is asked under a block
// number of its own (its device number), so that an intact answer names
// both the device and the question: one damaged header byte can make
// neither a device that is not there nor a found one.
class ScanListener {
public:
    ScanListener(int pcNumber, int patienceMs) : m_pc(pcNumber), m_patienceMs(patienceMs) {
        m_clock.start();
    }

    static int blockFor(int device) { return device; }

    void asking(int device) { m_asked.append({m_clock.elapsed(), device}); }

    void hear(const Incoming& in) {
        if (in.source >= 0 && in.sequence == blockFor(in.source) && wasAsked(in.source)) {
            m_found.insert(in.source);
            return;
        }
        const bool damaged = in.kind == Incoming::Damaged;
        if (!damaged && !looksLikeReplyToUs(in.wire)) return;
        // An answer to us that names nobody for sure: the numbers asked in
        // the last turnaround, and the one its header names, get a last look.
        const qint64 since = m_clock.elapsed() - m_patienceMs;
        for (auto it = m_asked.crbegin(); it != m_asked.crend() && it->first >= since; ++it)
            m_suspects.insert(it->second);
        if (!m_asked.isEmpty()) m_suspects.insert(m_asked.last().second);
        const int named = in.wire.isEmpty() ? -1 : quint8(in.wire.at(0)) - 0x40;
        if (named >= 0 && named < 64) m_suspects.insert(named);
    }

    void found(int device) { m_found.insert(device); }
    const QSet<int>& found() const { return m_found; }
    QSet<int> suspects() const { return m_suspects - m_found; }

private:
    bool wasAsked(int device) const {
        for (const auto& asked : m_asked)
            if (asked.second == device) return true;
        return false;
    }
    // Multiuser replies start with 0x40 + device, 0x80 + PC number.
    bool looksLikeReplyToUs(const QByteArray& wire) const {
        return wire.size() >= 2 && quint8(wire.at(1)) == 0x80 + m_pc;
    }

    int m_pc;
    int m_patienceMs;
    QElapsedTimer m_clock;
    QList<std::pair<qint64, int>> m_asked;  // (ms, device), in order
    QSet<int> m_found;
    QSet<int> m_suspects;
};

}  // namespace

Result<QList<int>> AsciiCamCon::scanBus(int first, int last, int timeoutMs,
                                        const ProgressFn& progress) {
    if (m_link.settings().framing != Framing::Multiuser) {
        return Error::unsupported(QCoreApplication::translate(
            "cambench::comm",
            "a bus scan needs the Multiuser protocol; connect with --protocol multiuser"));
    }
    first = qBound(0, first, 63);
    last = qBound(first, last, 63);
    const ScanGuard guard(m_link);
    if (timeoutMs > 0) m_link.setTimeout(timeoutMs);
    const int patienceMs = m_link.settings().timeoutMs > 0
                               ? m_link.settings().timeoutMs
                               : m_link.engine().settings().line.turnaroundMs;
    ScanListener listener(m_link.settings().pcNumber, patienceMs);
    m_link.engine().setIncomingObserver([&listener](const Incoming& in) { listener.hear(in); });

    const int count = last - first + 1;
    int step = 0;
    const auto look = [&](int device) -> Status {
        if (progress) progress(step, 2 * count);
        listener.asking(device);
        const Result<bool> answered =
            m_link.ping(device, ScanListener::blockFor(device), kQuickTurnaroundMs);
        if (!answered) return answered.error();
        if (*answered) listener.found(device);
        return success();
    };
    // Two quick looks: every number, then the ones still silent (a lost
    // reply), each followed by a turnaround of listening for late answers.
    for (int pass = 0; pass < 2; ++pass) {
        for (int device = first; device <= last; ++device, ++step) {
            if (pass == 1 && listener.found().contains(device)) continue;
            if (const Status looked = look(device); !looked) return looked.error();
        }
        if (const Status heard = m_link.engine().listen(patienceMs); !heard) return heard.error();
    }
    // A patient look, with retries, where damaged answers came from.
    m_link.engine().setIncomingObserver({});
    for (int device : listener.suspects()) {
        if (device < first || device > last) continue;
        m_link.setDevice(device);
        const Result<Fields> reply = m_link.call('?', "UNIT");
        if (reply) {
            listener.found(device);
        } else if (reply.error().kind == ErrorKind::Cancelled) {
            return reply.error();
        } else if (reply.error().kind != ErrorKind::Communication) {
            listener.found(device);  // it answered, if with an error
        }
    }
    QList<int> found = listener.found().values();
    std::sort(found.begin(), found.end());
    if (progress) progress(2 * count, 2 * count);
    return found;
}

Result<QList<int>> AsciiCamCon::scanBus(int first, int last, const ProgressFn& progress) {
    return scanBus(first, last, 0, progress);
}

}  // namespace cambench::comm
