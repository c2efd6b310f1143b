#include "sim_device.h"
#include "sim_handlers.h"

namespace cambench::comm {

namespace {

constexpr int kFirstArea = 0x08;  // O
constexpr int kLastArea = 0x0B;   // X
constexpr int kMaxNumber = 248;

bool validAddress(const Fields& r) {
    const qint64 area = r.num("area");
    const qint64 number = r.num("number");
    return area >= kFirstArea && area <= kLastArea && number >= 0 && number <= kMaxNumber;
}

SimPlcKey keyOf(const Fields& r) {
    return {int(r.num("area")), int(r.num("number"))};
}

Fields networkFields(const SimPlcKey& key, const SimPlcNetwork& network) {
    QList<qint64> symbols;
    for (quint16 symbol : network.symbols) symbols.append(symbol);
    Fields fields;
    fields.set("area", key.first).set("number", key.second).set("value", network.value);
    fields.set("reset", network.reset).setWords("symbols", symbols);
    return fields;
}

// Empty networks are not kept, so a cleared network leaves no trace.
void store(QMap<SimPlcKey, SimPlcNetwork>& networks, const SimPlcKey& key,
           const SimPlcNetwork& network) {
    if (network.isEmpty()) {
        networks.remove(key);
    } else {
        networks.insert(key, network);
    }
}

void registerMatrix(SimDevice& d) {
    d.addHandler(kQuery, "GMXSPS", [&d](const Fields& r) {
        if (!validAddress(r)) return SimResult::error(sim_errors::kUnknown);
        return SimResult::data(networkFields(keyOf(r), d.state().plcNetworks.value(keyOf(r))));
    });
    d.addHandler(kCommand, "GMXSPS", [&d](const Fields& r) {
        const QList<qint64> symbols = r.words("symbols");
        if (!validAddress(r) || symbols.size() != SimPlcNetwork::kSymbols) {
            return SimResult::error(sim_errors::kUnknown);
        }
        SimPlcNetwork network;
        network.value = qint32(r.num("value"));
        network.reset = quint16(r.num("reset"));
        for (int i = 0; i < SimPlcNetwork::kSymbols; ++i)
            network.symbols[i] = quint16(symbols.at(i));
        store(d.state().plcNetworks, keyOf(r), network);
        return SimResult::ok();
    });
}

// The set value of a timer or counter is its network's value field; the
// actual value runs on the device and is not stored in the EEPROM.
void registerTimers(SimDevice& d) {
    d.addHandler(kQuery, "SPSIST", [&d](const Fields& r) {
        if (!validAddress(r)) return SimResult::error(sim_errors::kUnknown);
        Fields reply;
        reply.set("value", d.runtime().plcActuals.value(keyOf(r)));
        return SimResult::data(reply);
    });
    d.addHandler(kCommand, "SPSIST", [&d](const Fields& r) {
        if (!validAddress(r)) return SimResult::error(sim_errors::kUnknown);
        d.runtime().plcActuals.insert(keyOf(r), qint32(r.num("value")));
        return SimResult::ok();
    });
    d.addHandler(kQuery, "SPSSOLL", [&d](const Fields& r) {
        if (!validAddress(r)) return SimResult::error(sim_errors::kUnknown);
        Fields reply;
        reply.set("value", d.state().plcNetworks.value(keyOf(r)).value);
        return SimResult::data(reply);
    });
    d.addHandler(kCommand, "SPSSOLL", [&d](const Fields& r) {
        if (!validAddress(r)) return SimResult::error(sim_errors::kUnknown);
        SimPlcNetwork network = d.state().plcNetworks.value(keyOf(r));
        network.value = qint32(r.num("value"));
        store(d.state().plcNetworks, keyOf(r), network);
        return SimResult::ok();
    });
}

}  // namespace

void registerPlcHandlers(SimDevice& device) {
    registerMatrix(device);
    registerTimers(device);
}

}  // namespace cambench::comm
