#include "cambus_camcon.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <algorithm>

namespace cambench::comm {

namespace {

// A bus that is searching its users (an initialisation phase, ~2 s) passes
// the token after it; longer silence means there is no bus.
constexpr int kLearnLimitMs = 4000;
constexpr int kLearnSliceMs = 50;
// Detect listens this long: a running bus passes the token many times.
constexpr int kProbeMs = 1500;

std::unique_ptr<AsciiLink> makeLink(Transport& transport, const AsciiSettings& settings,
                                    const LineTiming& line, const CamBusStationConfig& station,
                                    CamBusMonitorPtr monitor) {
    AsciiSettings ascii = settings;
    ascii.framing = Framing::Standard;  // no block numbers; the block bit is the bus's own
    return std::make_unique<AsciiLink>(
        transport, ascii, line,
        std::make_unique<CamBusBackend>(settings.device, station, std::move(monitor)));
}

// A round: every user the view holds got the token since `since`.
bool roundSeen(const CamBusView& view, qint64 since) {
    if (view.users.isEmpty() || view.inInitPhase) return false;
    return std::all_of(view.users.cbegin(), view.users.cend(),
                       [since](const CamBusUserState& user) { return user.lastTokenMs >= since; });
}

}  // namespace

CamBusCamCon::CamBusCamCon(Transport& transport, const AsciiSettings& settings,
                           const LineTiming& line, const CamBusStationConfig& station,
                           CamBusMonitorPtr monitor)
    : AsciiCamCon(makeLink(transport, settings, line, station, std::move(monitor))),
      m_bus(static_cast<CamBusBackend&>(link().backend())) {}

QString CamBusCamCon::protocolId() const {
    return QStringLiteral("cambus");
}

bool CamBusCamCon::has(CamConCapability capability) const {
    if (capability == CamConCapability::BusScan) return true;
    return AsciiCamCon::has(capability);
}

Result<QString> CamBusCamCon::probe() {
    m_bus.setListenOnly(true);
    QElapsedTimer clock;
    clock.start();
    // A bus that is forming (breaks, an RID search) passes the token a
    // couple of seconds later: worth the wait.
    const auto limit = [this] {
        const CamBusView view = m_bus.view();
        return view.initPhases > 0 || view.inInitPhase ? kLearnLimitMs + kProbeMs : kProbeMs;
    };
    while (clock.elapsed() < limit()) {
        if (const Status heard = link().engine().listen(kLearnSliceMs); !heard)
            return heard.error();
        const CamBusView view = m_bus.view();
        if (view.tokens >= 2 * qMax(1, int(view.users.size())) && !view.users.isEmpty()) {
            QStringList users;
            for (int number : view.users.keys()) users << QString::number(number);
            return QCoreApplication::translate("cambench::comm",
                                               "a Cam-BUS: users %1 get the token; which of them "
                                               "are CamCons, a scan tells")
                .arg(users.join(QStringLiteral(", ")));
        }
    }
    return Error::communication(
        QCoreApplication::translate("cambench::comm", "no Cam-BUS token heard in %1 s")
            .arg(kProbeMs / 1000.0, 0, 'f', 1));
}

Status CamBusCamCon::learnRound() {
    QElapsedTimer clock;
    clock.start();
    // Tokens heard from now on count (the view's clock is the engine's).
    qint64 since = -1;
    while (clock.elapsed() < kLearnLimitMs) {
        if (const Status heard = link().engine().listen(kLearnSliceMs); !heard) return heard;
        const CamBusView view = m_bus.view();
        if (since < 0) {
            since = view.nowMs > 0 ? view.nowMs : 0;
            for (const CamBusUserState& user : view.users)
                since = std::max(since, user.lastTokenMs);
            continue;
        }
        if (roundSeen(view, since + 1)) return success();
    }
    if (m_bus.view().users.isEmpty())
        return Error::communication(
            QCoreApplication::translate("cambench::comm",
                                        "no Cam-BUS traffic in %1 s on %2: no user passes the "
                                        "token; %3")
                .arg(kLearnLimitMs / 1000)
                .arg(link().engine().transport().description(), m_bus.checkHint()));
    return success();
}

Result<BusUsers> CamBusCamCon::scanUsers(const ProgressFn& progress) {
    const int device = link().settings().device;
    if (const Status learned = learnRound(); !learned) return learned.error();
    QMap<int, BusUser> found;
    const auto ask = [&](int number) -> Status {
        if (found.contains(number)) return success();
        BusUser user{number, BusUser::Other, false};
        if (number == m_bus.pcNumber()) {
            user.kind = BusUser::ThisPc;
        } else {
            const Result<bool> answered = link().ping(number, 0, -1);
            if (!answered) return answered.error();
            if (*answered) user.kind = BusUser::CamCon;
        }
        found.insert(number, user);
        return success();
    };
    // The first question makes the PC join (an initialisation phase), after
    // which the table is searched anew: ask whoever is new in it too.
    for (int pass = 0; pass < 2; ++pass) {
        const QList<int> users = m_bus.view().users.keys();
        int step = 0;
        for (int number : users) {
            if (progress) progress(step++, users.size());
            if (const Status asked = ask(number); !asked) {
                link().setDevice(device);
                return asked.error();
            }
        }
    }
    link().setDevice(device);
    // The table as it is now: a user of the first look that the PC's
    // joining dropped (an earlier run's PC) is not on the bus any more.
    const CamBusView view = m_bus.view();
    BusUsers result;
    result.kindsKnown = true;
    for (auto it = view.users.cbegin(); it != view.users.cend(); ++it) {
        BusUser user = found.value(it.key(), BusUser{it.key(), BusUser::Other, false});
        user.silent = !it->answers;
        result.users << user;
    }
    return result;
}

Result<QList<int>> CamBusCamCon::scanBus(int first, int last, const ProgressFn& progress) {
    const Result<BusUsers> users = scanUsers(progress);
    if (!users) return users.error();
    QList<int> camCons;
    for (const BusUser& user : users->users)
        if (user.kind == BusUser::CamCon && user.number >= first && user.number <= last)
            camCons << user.number;
    return camCons;
}

}  // namespace cambench::comm
