#include "sim_device.h"

#include "comm/sim/sim_log.h"
#include "sim_handlers.h"

#include "comm/camcon/ascii/command_codec.h"

#include <utility>

namespace cambench::comm {

namespace {

QByteArray handlerKey(char kind, QByteArrayView name) {
    return QByteArray(1, kind) + name.toByteArray();
}

}  // namespace

SimDevice::SimDevice(SimProfile profile, int number)
    : m_profile(std::move(profile)),
      m_number(number),
      m_eeprom(m_profile),
      m_axis(m_profile.minPosition, m_profile.maxPosition, m_profile.unitsPerSecond) {
    m_state = defaultState(m_profile, m_number);
    registerStatusHandlers(*this);
    registerCamHandlers(*this);
    registerNameHandlers(*this);
    registerUserHandlers(*this);
    registerPlcHandlers(*this);
    registerEepromHandlers(*this);
    registerInfoHandlers(*this);
    registerSettingsHandlers(*this);
}

void SimDevice::addHandler(char kind, const QByteArray& name, SimHandler handler) {
    m_handlers.insert(handlerKey(kind, name), std::move(handler));
}

void SimDevice::forgetCommand(char kind, const QByteArray& name) {
    m_handlers.remove(handlerKey(kind, name));
}

bool SimDevice::hasHandler(char kind, const QByteArray& name) const {
    return m_handlers.contains(handlerKey(kind, name));
}

std::optional<SimResult> SimDevice::call(char kind, const QByteArray& name, const Fields& fields) {
    const auto handler = m_handlers.constFind(handlerKey(kind, name));
    if (handler == m_handlers.cend()) return std::nullopt;
    return (*handler)(fields);
}

void SimDevice::clearAll() {
    m_state = defaultState(m_profile, m_number);
    m_cursor.reset();
    m_runtime = SimRuntime();
    m_tableState = SimTableState();
}

void SimDevice::start(SimState state) {
    m_state = std::move(state);
    m_cursor.reset();
    m_axis.setRunning(true);
}

void SimDevice::erase() {
    clearAll();
    m_state.settings.clear();
    m_axis.setRunning(false);
}

std::optional<SimDevice::Reply> SimDevice::execute(const Frame& request) {
    ++m_executions;
    const CommandSpec* spec = matchRequest(request.lead, request.body);
    const auto handler =
        spec ? m_handlers.constFind(handlerKey(spec->kind, spec->name)) : m_handlers.cend();
    SimResult result;
    Reply reply;
    reply.frame.lead = kReply;
    if (handler == m_handlers.cend()) {
        qCDebug(commSimLog) << "device" << m_number << "does not understand" << request.lead
                            << request.body.left(12);
        reply.frame.body = notUnderstoodBody(m_profile.epromDate);
    } else {
        const Result<Fields> fields = decodeRequestFields(*spec, request.body);
        if (fields) {
            result = (*handler)(*fields);
        } else {
            qCDebug(commSimLog) << "malformed" << spec->name << ":" << fields.error().message;
            result = SimResult::error(sim_errors::kUnknown);
        }
        if (result.kind == SimResult::NoReply) return std::nullopt;
        reply.frame.body = replyBody(*spec, result);
    }
    // Set after the handler: the reply to !C0 already goes without checksum.
    reply.frame.hasChecksum = m_checksums;
    reply.delayMs = m_profile.processingDelayMs + result.delayMs;
    return reply;
}

QByteArray SimDevice::replyBody(const CommandSpec& spec, const SimResult& result) const {
    switch (result.kind) {
        case SimResult::Data: {
            const Result<QByteArray> body = encodeReplyBody(spec, result.fields);
            if (body) return *body;
            qCWarning(commSimLog) << "cannot encode reply to" << spec.name << ":"
                                  << body.error().message;
            return errorReplyBody(spec, sim_errors::kUnknown);
        }
        case SimResult::Error:
            return errorReplyBody(spec, result.code);
        case SimResult::Ok:
        case SimResult::NoReply:
            break;
    }
    return okReplyBody(spec);
}

}  // namespace cambench::comm
