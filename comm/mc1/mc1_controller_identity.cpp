// Mc1Controller: what tells two controllers apart (Mc1Device::readIdentity).
#include "mc1_controller.h"

namespace cambench::comm {

Result<DeviceIdentity> Mc1Controller::readIdentity() {
    Result<DeviceIdentity> identity = Mc1Device::readIdentity();
    if (!identity) return identity;
    DeviceIdentity found = *identity;
    if (isMc200(variant())) {
        // RDTABLE (manual 3.12) of every logical axis: the physical coding
        // and type of those it has; a refusal (NAK) is an axis it lacks.
        QStringList table;
        for (int axis = kMc1FirstAxis; axis <= kMc1LastAxis; ++axis) {
            const Result<QByteArray> entry =
                m_link.exchange(Mc1Op::ReadTable, QByteArray(2, '\0') + mc1LittleEndian(axis, 1) +
                                                      QByteArray(1, '\0'));
            if (!entry && !isMc1Refusal(entry.error())) return entry.error();
            if (entry && entry->size() >= 2)
                table << QStringLiteral("%1:%2/%3")
                             .arg(axis)
                             .arg(quint8(entry->at(0)))
                             .arg(quint8(entry->at(1)));
        }
        found.set(QStringLiteral("axes"),
                  table.isEmpty() ? QStringLiteral("none") : table.join(QLatin1Char(' ')));
    }
    if (has(Mc1Capability::ProgramControl)) {
        // Where the PLC program's data block starts (SYSDATA 08): it moves
        // with the program loaded (provisional, comm/mc1/README.md).
        const Result<QByteArray> udb = m_link.exchange(Mc1Op::UdbAddress, {});
        if (!udb) return udb.error();
        found.set(
            QStringLiteral("program udb"),
            QStringLiteral("0x%1").arg(mc1FromLittleEndian(*udb, false), 8, 16, QLatin1Char('0')));
    }
    return found;
}

}  // namespace cambench::comm
