#include "sim_device.h"
#include "sim_handlers.h"

#include <QtEndian>

namespace cambench::comm {

namespace {

// Bytes of RAM a cam takes in the simulated device, for ?MRAMFREE.
constexpr qint64 kRamPerCam = 8;
constexpr qint64 kCycleTime = 5;  // ?GZYKLIST: 0.5 ms

Fields value(qint64 v) {
    Fields fields;
    fields.set("value", v);
    return fields;
}

void registerIdentity(SimDevice& d) {
    const SimProfile& p = d.profile();
    const auto constant = [&d](const char* name, qint64 v) {
        d.addHandler(kQuery, name, [v](const Fields&) { return SimResult::data(value(v)); });
    };
    d.addHandler(kQuery, "EPROM", [&p](const Fields&) {
        Fields reply;
        reply.setBytes("text", p.epromDate);
        return SimResult::data(reply);
    });
    constant("GCPUCLK", p.cpuClock);
    constant("GTEMP", p.temperature);
    constant("GTZKMAX", p.maxDeadTime);
    constant("MRAMMAX", p.ramSize);
    constant("MEES", p.serialEepromSize);
    constant("MPEE", p.parallelEepromSize);
    constant("IMIN", p.minPosition);
    constant("IMAX", p.maxPosition);
    constant("GPRGMAX", p.programs);
    constant("GZYKLIST", kCycleTime);
    constant("GBOOST", 0);
    d.addHandler(kQuery, "MEENOCK",
                 [&d](const Fields&) { return SimResult::data(value(d.state().cams.camCount())); });
    d.addHandler(kQuery, "MEEFREE", [&d](const Fields&) {
        return SimResult::data(value(d.profile().camCapacity - d.state().cams.camCount()));
    });
    d.addHandler(kQuery, "MEETZK", [&d](const Fields&) {
        return SimResult::data(value(d.state().deadTimes.size()));
    });
    d.addHandler(kQuery, "MRAMFREE", [&d](const Fields&) {
        return SimResult::data(value(
            std::max<qint64>(0, d.profile().ramSize - kRamPerCam * d.state().cams.camCount())));
    });
    // The unit number is in the Multiuser header: answering is the answer.
    d.addHandler(kQuery, "UNIT", [](const Fields&) { return SimResult::data({}); });
}

void registerControl(SimDevice& d) {
    d.addHandler(kCommand, "C0", [&d](const Fields&) {
        d.setChecksumsEnabled(false);
        return SimResult::ok();
    });
    d.addHandler(kCommand, "C1", [&d](const Fields&) {
        d.setChecksumsEnabled(true);
        return SimResult::ok();
    });
    d.addHandler(kCommand, "CA", [&d](const Fields&) {
        d.clearAll();
        return SimResult::ok(d.profile().clearDelayMs);
    });
    d.addHandler(kCommand, "GRESET", [&d](const Fields&) {
        d.cursor().reset();
        d.runtime().errorState = 0;
        return SimResult::none();
    });
    d.addHandler(kCommand, "A0", [](const Fields&) { return SimResult::ok(); });
}

// ?ML / !MS / !MW on a small fake RAM, big-endian like the 68k CamCons.
void registerRam(SimDevice& d) {
    const auto fits = [&d](qint64 address, int bytes) {
        return address >= 0 && address + bytes <= d.runtime().ram.size();
    };
    d.addHandler(kQuery, "ML", [&d, fits](const Fields& r) {
        const qint64 address = r.num("address");
        if (!fits(address, 4)) return SimResult::error(sim_errors::kUnknown);
        Fields reply;
        reply.set("address", address)
            .set("value", qFromBigEndian<quint32>(d.runtime().ram.constData() + address));
        return SimResult::data(reply);
    });
    d.addHandler(kCommand, "MS", [&d, fits](const Fields& r) {
        const qint64 address = r.num("address");
        if (!fits(address, 1)) return SimResult::error(sim_errors::kUnknown);
        d.runtime().ram[address] = char(r.num("value"));
        return SimResult::ok();
    });
    d.addHandler(kCommand, "MW", [&d, fits](const Fields& r) {
        const qint64 address = r.num("address");
        if (!fits(address, 2)) return SimResult::error(sim_errors::kUnknown);
        qToBigEndian<quint16>(quint16(r.num("value")), d.runtime().ram.data() + address);
        return SimResult::ok();
    });
}

}  // namespace

void registerInfoHandlers(SimDevice& device) {
    registerIdentity(device);
    registerControl(device);
    registerRam(device);
}

}  // namespace cambench::comm
