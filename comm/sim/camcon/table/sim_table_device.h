#pragma once

#include "sim_table_areas.h"

#include "comm/camcon/table/rk512.h"

#include <QByteArray>

#include <optional>

namespace cambench::comm {

class SimDevice;

// A simulated CamCon's table interface above 3964R: executes one telegram
// (RK512, or a short command 0x01..0x07) on the device's state and makes
// its reply telegram.
class SimTableDevice {
public:
    SimTableDevice(SimDevice& device, table::Rk512Variant variant);

    // The reply, or nullopt when the device sends none (hardware reset).
    std::optional<QByteArray> execute(const QByteArray& telegram);

    table::Rk512Variant variant() const { return m_variant; }

private:
    std::optional<QByteArray> executeRk512(const QByteArray& telegram);
    QByteArray executeShort(const QByteArray& telegram);  // sim_table_short_commands.cpp

    SimDevice& m_device;
    table::Rk512Variant m_variant;
    SimTableAreas m_areas;
};

}  // namespace cambench::comm
