#include "sim_line.h"

#include "comm/sim/sim_log.h"

#include "comm/camcon/ascii/catalogue.h"
#include "comm/camcon/ascii/command_codec.h"

#include <algorithm>

namespace cambench::comm {

SimLine::SimLine(Framing framing)
    : m_framing(framing), m_decoder(framing, QByteArrayLiteral("?!")) {}

SimDevice& SimLine::addDevice(std::unique_ptr<SimDevice> device) {
    m_devices.push_back(std::move(device));
    updateChecksumMode();
    return *m_devices.back();
}

SimDevice* SimLine::device(int number) const {
    for (const auto& device : m_devices) {
        if (device->number() == number) return device.get();
    }
    return nullptr;
}

void SimLine::updateChecksumMode() {
    // One decoder serves every device on the line: checksums are expected
    // only while all of them expect one (!C0 is meant for terminals).
    m_decoder.setChecksumEnabled(std::all_of(m_devices.begin(), m_devices.end(),
                                             [](const auto& d) { return d->checksumsEnabled(); }));
}

QString SimLine::protocolName() const {
    return m_framing == Framing::Multiuser ? QStringLiteral("Multiuser")
                                           : QStringLiteral("Standard");
}

QList<SimOutput> SimLine::feed(QByteArrayView bytesFromPc) {
    QList<SimOutput> outputs;
    for (const DecodeEvent& event : m_decoder.feed(bytesFromPc)) {
        if (event.kind == DecodeEvent::BadChecksum) {
            ++m_counters.badChecksums;
            qCDebug(commSimLog) << "bad checksum, no answer:" << event.detail;
            continue;
        }
        if (event.kind != DecodeEvent::FrameOk) continue;
        ++m_counters.frames;
        if (m_faults.ignoresRequest()) {
            qCDebug(commSimLog) << "request missed (fault injection)";
            continue;
        }
        std::optional<SimOutput> output = answer(event.frame);
        if (output) output = m_faults.apply(*output, event.frame.lead + event.frame.body);
        if (output) outputs.append(*output);
    }
    return outputs;
}

std::optional<SimOutput> SimLine::answer(const Frame& request) {
    if (m_framing == Framing::Standard || !request.address) {
        if (m_devices.empty() || m_injections.isDead(m_devices.front()->number()))
            return std::nullopt;
        return execute(*m_devices.front(), request);
    }
    const MultiuserAddress& address = *request.address;
    SimDevice* target = device(address.destination);
    if (!target || (m_pcNumber && address.source != *m_pcNumber)) {
        ++m_counters.unaddressed;
        return std::nullopt;
    }
    if (m_injections.isDead(target->number())) return std::nullopt;
    LastAnswer& last = m_lastAnswers[target->number()][address.source];
    if (last.block == address.block) {
        ++m_counters.repeats;
        qCDebug(commSimLog) << "device" << target->number() << "repeats block" << address.block;
        return last.output;
    }
    last.block = address.block;
    last.output = execute(*target, request);
    return last.output;
}

std::optional<SimOutput> SimLine::execute(SimDevice& device, const Frame& request) {
    // Only the command name: data may hold secrets (user numbers).
    const CommandSpec* spec = matchRequest(request.lead, request.body);
    qCDebug(commSimLog).noquote() << "device" << device.number() << "<-"
                                  << QString(QChar(request.lead))
                                  << (spec ? spec->name : "(unknown)") << request.body.size()
                                  << "bytes";
    m_injections.record(device.number(), request.lead,
                        spec ? QByteArray(spec->name) : QByteArrayLiteral("(unknown)"));
    std::optional<SimDevice::Reply> reply;
    if (const std::optional<qint32> refused =
            spec ? m_injections.takeRefusal(device.number(), spec->kind, spec->name)
                 : std::nullopt) {
        reply = SimDevice::Reply{};
        reply->frame.lead = kReply;
        reply->frame.body = errorReplyBody(*spec, *refused);
        reply->frame.hasChecksum = device.checksumsEnabled();
    } else {
        reply = device.execute(request);
    }
    updateChecksumMode();
    if (!reply) return std::nullopt;
    if (request.address) {
        reply->frame.address =
            MultiuserAddress{device.number(), request.address->source, request.address->block};
    }
    return SimOutput{encodeFrame(reply->frame), reply->delayMs};
}

}  // namespace cambench::comm
