#include "sim_handlers.h"

namespace cambench::comm {

namespace {

Fields number(qint64 value) {
    return Fields{{"value", QVariant::fromValue(value)}};
}
Fields text(const char* value) {
    return Fields{{"text", QByteArray(value)}};
}

}  // namespace

SimState defaultState(const SimProfile& profile, int deviceNumber) {
    SimState state;
    state.cams = SimCamStore(profile.minPosition, profile.maxPosition, profile.camCapacity);
    // Settings that are not 0 on a cleared device; everything else reads 0.
    const QList<std::pair<const char*, Fields>> defaults{
        {"GEBER", number(1)},  // SSI 360 Gray singleturn: matches 0..359
        {"GTXT1", text("SSI 360 Gray")},
        {"GTXT2", text("Singleturn")},
        {"IMUL", number(1)},
        {"IDIV", number(1)},
        {"IFOR", text("###")},
        {"SFAK", number(100000)},  // 1.00000
        {"SFOR", text("####")},
        {"S100", number(1000)},
        {"SEXA", number(100)},  // 1.00
        {"GKL", number(10)},
        {"EMAX", number(profile.inputs)},
        {"AMAX", number(profile.outputs)},
        {"GTZKANZ", number(profile.outputs)},
        {"GSIO", number(profile.protocol)},
        // Table interface area 203 word 38: the areas 241.. that exist.
        {"ANOCK", number(profile.analogChannels)},
        {"GNR", number(deviceNumber)},
        {"GONSPS", number(1)},
        {"GESPSMAX", number(16)},
        {"GASPSMAX", number(16)},
        {"GMSPSMAX", number(32)},
        {"GXSPSMAX", number(16)},
        {"GTSPSMAX", number(16)},
        {"GVSPSMAX", number(8)},
        {"GSSPSMAX", number(8)},
    };
    for (const auto& [name, fields] : defaults)
        state.settings.insert({QByteArray(name), -1}, fields);
    return state;
}

}  // namespace cambench::comm
