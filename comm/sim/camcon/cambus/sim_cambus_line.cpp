#include "sim_cambus_line.h"

#include "comm/sim/sim_log.h"

namespace cambench::comm {

qint64 SimPcAnswers::count() const {
    qint64 total = 0;
    for (qint64 n : countByMs) total += n;
    return total;
}

qint64 SimPcAnswers::medianMs() const {
    const qint64 half = (count() + 1) / 2;
    qint64 seen = 0;
    for (auto it = countByMs.cbegin(); it != countByMs.cend(); ++it) {
        seen += *it;
        if (seen >= half) return it.key();
    }
    return -1;
}

qint64 SimPcAnswers::worstMs() const {
    return countByMs.isEmpty() ? -1 : countByMs.lastKey();
}

SimCamBusLine::SimCamBusLine(std::vector<std::unique_ptr<SimDevice>> devices, const Setup& setup,
                             qint64 nowMs)
    : m_medium(setup.baud) {
    m_medium.setFaults(setup.faults);
    QSet<int> simulated(setup.displays.cbegin(), setup.displays.cend());
    for (const auto& device : devices) simulated.insert(device->number());
    const int answerMs = setup.station.answerMs;
    const int pcAnswerMs = setup.pcAnswerMs;
    // Every simulated user: the bus's baud rate, the simulator's rules. The
    // PC's number is learnt from its answers (receive()); a number nobody
    // answered for gets T, or a search of 64 numbers would take ages.
    CamBusStationConfig station = setup.station;
    station.baud = setup.baud;
    station.joinBeforeFirstBlock = false;
    auto external = m_external;
    station.answerMsFor = [simulated, external, answerMs, pcAnswerMs](int user) {
        return !simulated.contains(user) && external->contains(user) ? pcAnswerMs : answerMs;
    };
    for (std::unique_ptr<SimDevice>& device : devices) {
        CamBusStationConfig config = station;
        config.number = device->number();
        auto camCon = std::make_unique<SimCamBusCamCon>(std::move(device), config, nowMs);
        if (setup.silent.contains(config.number) && setup.silentFromMs <= 0)
            camCon->station().setSilent(true);
        m_medium.attach(camCon.get());
        m_camCons.push_back(std::move(camCon));
    }
    if (setup.silentFromMs > 0) {
        m_fallSilent = setup.silent;
        m_silentFromMs = setup.silentFromMs;
    }
    m_reinitAtMs = setup.reinitAtMs;
    m_pcAnswerMs = pcAnswerMs;
    // Every simulated user hears every answer: one of them counts the PC's.
    if (!m_camCons.empty())
        m_camCons.front()->station().setAnswerObserver([this, simulated](int user, qint64 ms) {
            if (!simulated.contains(user) && m_external->contains(user)) notePcAnswer(user, ms);
        });
    for (int i = 0; i < setup.displays.size(); ++i) {
        CamBusStationConfig config = station;
        config.number = setup.displays.at(i);
        const int target =
            m_camCons.empty() ? 0 : m_camCons.at(i % m_camCons.size())->device().number();
        auto display = std::make_unique<SimCamBusDisplay>(target, config, nowMs);
        m_medium.attach(display.get());
        m_displays.push_back(std::move(display));
    }
}

SimCamBusDisplay* SimCamBusLine::display(int index) const {
    return index >= 0 && index < int(m_displays.size()) ? m_displays.at(index).get() : nullptr;
}

void SimCamBusLine::applyScheduledFaults(qint64 nowMs) {
    if (m_silentFromMs >= 0 && nowMs >= m_silentFromMs) {
        m_silentFromMs = -1;
        for (int number : m_fallSilent)
            if (SimCamBusCamCon* user = camCon(number)) user->station().setSilent(true);
    }
    if (m_reinitAtMs >= 0 && nowMs >= m_reinitAtMs && !m_camCons.empty()) {
        m_reinitAtMs = -1;
        m_camCons.front()->station().breakIn(nowMs);
    }
}

SimCamBusLine::~SimCamBusLine() {
    if (m_pcAnswers.count() == 0 && m_pcAnswers.missed == 0) return;
    qCInfo(commSimLog).noquote()
        << QStringLiteral(
               "Cam-BUS: the PC answered %1 times, median %2 ms, worst %3 ms after the byte it "
               "answered; %4 answers did not come within %5 ms")
               .arg(m_pcAnswers.count())
               .arg(m_pcAnswers.medianMs())
               .arg(m_pcAnswers.worstMs())
               .arg(m_pcAnswers.missed)
               .arg(m_pcAnswerMs);
}

void SimCamBusLine::notePcAnswer(int user, qint64 ms) {
    // A PC that has closed its port stays in the table (P4) and misses
    // every turn until the next initialisation phase: misses count once the
    // PC answers again in the same table.
    const int initPhases = m_camCons.front()->station().view().initPhases;
    if (initPhases != m_initPhasesSeen) {
        m_initPhasesSeen = initPhases;
        m_pcMissesPending = 0;
    }
    if (ms < 0) {
        ++m_pcMissesPending;
        return;
    }
    ++m_pcAnswers.countByMs[ms];
    if (m_pcMissesPending == 0) return;
    m_pcAnswers.missed += m_pcMissesPending;
    qCInfo(commSimLog).noquote()
        << QStringLiteral(
               "Cam-BUS: the PC (user %1) let %2 turn(s) in a row go by without an answer "
               "within %3 ms, then answered again (%4 missed in all)")
               .arg(user)
               .arg(m_pcMissesPending)
               .arg(m_pcAnswerMs)
               .arg(m_pcAnswers.missed);
    m_pcMissesPending = 0;
}

SimCamBusCamCon* SimCamBusLine::camCon(int number) const {
    for (const auto& camCon : m_camCons)
        if (camCon->device().number() == number) return camCon.get();
    return nullptr;
}

SimDevice* SimCamBusLine::device(int number) const {
    SimCamBusCamCon* camCon = this->camCon(number);
    return camCon ? &camCon->device() : nullptr;
}

QList<SimOutput> SimCamBusLine::outputs(const QByteArray& bytes) {
    if (bytes.isEmpty()) return {};
    return {SimOutput{bytes, 0}};
}

QList<SimOutput> SimCamBusLine::receive(QByteArrayView bytes, qint64 nowMs) {
    for (char c : bytes) {
        const CamBusByteKind kind = camBusKind(quint8(c));
        if (kind == CamBusByteKind::Ack || kind == CamBusByteKind::Nak)
            m_external->insert(camBusUser(quint8(c)));
    }
    m_medium.inject(bytes.toByteArray(), nowMs);
    applyScheduledFaults(nowMs);
    return outputs(m_medium.advance(nowMs));
}

QList<SimOutput> SimCamBusLine::poll(qint64 nowMs) {
    applyScheduledFaults(nowMs);
    return outputs(m_medium.advance(nowMs));
}

qint64 SimCamBusLine::nextTimerMs() const {
    qint64 next = m_medium.nextTimerMs();
    for (qint64 at : {m_silentFromMs, m_reinitAtMs})
        if (at >= 0 && (next < 0 || at < next)) next = at;
    return next;
}

}  // namespace cambench::comm
