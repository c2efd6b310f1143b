#include "sim_cambus_line.h"

namespace cambench::comm {

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
