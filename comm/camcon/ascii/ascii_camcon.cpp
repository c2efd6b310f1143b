#include "ascii_camcon.h"

#include <QCoreApplication>

#include "traffic_mask.h"

namespace cambench::comm {

AsciiCamCon::AsciiCamCon(Transport& transport, const AsciiSettings& settings,
                         const LineTiming& line)
    : m_ownLink(std::make_unique<AsciiLink>(transport, settings, line)), m_link(*m_ownLink) {}

AsciiCamCon::AsciiCamCon(AsciiLink& link) : m_link(link) {}

AsciiCamCon::AsciiCamCon(std::unique_ptr<AsciiLink> link)
    : m_ownLink(std::move(link)), m_link(*m_ownLink) {}

AsciiCamCon::~AsciiCamCon() = default;

QString AsciiCamCon::protocolId() const {
    return m_link.settings().framing == Framing::Multiuser ? QStringLiteral("multiuser")
                                                           : QStringLiteral("standard");
}

bool AsciiCamCon::has(CamConCapability capability) const {
    switch (capability) {
        case CamConCapability::Users:
        case CamConCapability::EepromBackup:
        case CamConCapability::Terminal:
        case CamConCapability::OutputNames:
        case CamConCapability::PlcNetworks:
            return true;
        case CamConCapability::BusScan:
            return m_link.settings().framing == Framing::Multiuser;
        case CamConCapability::DeadTimeModes:
        case CamConCapability::AnalogueCams:
        case CamConCapability::EepromLock:
        case CamConCapability::ProgrammingProgram:
        case CamConCapability::ShortCommands:
            return false;
    }
    return false;
}

Result<QByteArray> AsciiCamCon::raw(const QByteArray& request) {
    if (request.isEmpty())
        return Error::usage(QCoreApplication::translate(
            "cambench::comm", "an empty request: type ? or ! and the command"));
    const Result<QByteArray> reply = m_link.raw(request.at(0), request.mid(1));
    if (!reply) return reply.error();
    // User numbers are secrets on the screen too, not only in the log.
    return maskSecrets(kReply + *reply, false).mid(1);
}

}  // namespace cambench::comm
