#include "sim_demo.h"

#include "cambus/sim_cambus_line.h"

#include "sim_device.h"
#include "sim_line.h"

#include "comm/sim/camcon/table/sim_table_line.h"

#include <algorithm>

namespace cambench::comm {

namespace {

void addCams(SimDevice& device, int program, int output, const QList<Cam>& cams) {
    for (const Cam& cam : cams) device.state().cams.insert(program, output, cam);
}

SimUser demoUser(const char* name, const char* number, quint32 rights, int outputs) {
    SimUser user;
    user.name = name;
    user.number = number;
    user.rights = rights;
    for (int output = 0; output < outputs; ++output) {
        user.access[output / 8] = char(user.access.at(output / 8) | (1 << (output % 8)));
    }
    user.allOutputs = outputs >= SimUser::kAccessBytes * 8;
    return user;
}

}  // namespace

void loadDemoState(SimDevice& device) {
    SimState& state = device.state();
    const qint32 max = device.profile().maxPosition;
    addCams(device, 0, 0, {{10, 90}, {180, 270}});
    addCams(device, 0, 1, {{max - 20, 30}});  // wraps through zero
    addCams(device, 0, 2, {{0, 45}, {90, 135}, {180, 225}, {270, 315}});
    addCams(device, 1, 0, {{45, 200}});
    addCams(device, 1, 3, {{100, 110}, {300, 350}});
    addCams(device, 2, 5, {{5, 355}});
    state.programNames = {{0, "Standard"}, {1, "Format A4"}, {2, "Cleaning"}};
    state.outputNames = {
        {0, "Glue valve"}, {1, "Knife"}, {2, "Stacker"}, {3, "Punch"}, {5, "Blower"}};
    state.deadTimes = {{0, 25}, {1, 120}, {3, 9999}};
    // Only the table interface reaches these.
    SimTableState& table = device.tableState();
    table.deadTimeModes.insert(1, {DeadTimeMode::SeparateOnOff, 0, 80, 150});
    if (device.profile().analogChannels > 0)
        table.analogueCams.insert(0, {{0, 0}, {max / 2, 16000}, {max, 0}});
    state.users = {demoUser("Supervisor", "4711", 0xEF, 256),
                   demoUser("Operator", "1234", 0x01, 8)};
    SimPlcNetwork andGate;  // O0 = I1 AND M2
    andGate.symbols[0] = 0x0101;
    andGate.symbols[1] = 0x0A02;
    state.plcNetworks.insert({0x08, 0}, andGate);
    SimPlcNetwork timer;
    timer.value = 500;
    timer.symbols[0] = 0x0103;
    state.plcNetworks.insert({0x0A, 4}, timer);
    device.runtime().plcActuals.insert({0x0A, 4}, 120);
    state.userTexts = {{0, "CamBench demo"}, {1, "Simulated CamCon"}};
}

void fillBenchmarkCams(SimDevice& device, int camsPerTrack) {
    const SimProfile& profile = device.profile();
    const qint64 span = qint64(profile.maxPosition) - profile.minPosition + 1;
    const int count = int(std::min<qint64>(camsPerTrack, span / 2));
    SimCamStore& cams = device.state().cams;
    cams.clear();
    if (count <= 0) return;
    const qint64 width = span / count;
    for (int program = 0; program < profile.programs; ++program) {
        for (int output = 0; output < profile.outputs; ++output) {
            for (int i = 0; i < count; ++i) {
                const auto on = qint32(profile.minPosition + i * width);
                cams.insert(program, output, {on, qint32(on + std::max<qint64>(1, width / 2))});
            }
        }
    }
}

void fillUsers(SimDevice& device, int count) {
    QList<SimUser>& users = device.state().users;
    users.clear();
    for (int i = 1; i <= std::min(count, device.profile().maxUsers); ++i) {
        const QByteArray name = QByteArray("User ") + QByteArray::number(i).rightJustified(2, '0');
        users.append(
            demoUser(name.constData(), QByteArray::number(1000 + i).constData(), 0x01, i % 32));
    }
}

namespace {

// The profile `config` asks for: protocol number and room for its cams.
SimProfile sizedProfile(const SimPortConfig& config, const SimProfile& profile) {
    SimProfile sized = profile;
    // The device's "Ser.mode" (table interface DW11): 0 Cam-BUS, 1
    // Standard, 2 Multiuser, 4 3964R.
    sized.protocol = config.camBus                                     ? 0
                     : config.tableVariant                             ? 4
                     : config.effectiveFraming() == Framing::Multiuser ? 2
                                                                       : 1;
    sized.analogChannels = config.analogueOutputs;
    if (!config.epromDate.isEmpty()) sized.epromDate = config.epromDate;
    if (config.outputs > 0) sized.outputs = config.outputs;
    sized.camCapacity =
        std::max<qint32>(profile.camCapacity, profile.programs * sized.outputs * config.fill);
    return sized;
}

std::unique_ptr<SimDevice> makeDevice(const SimPortConfig& config, const SimProfile& profile,
                                      int number) {
    auto device = std::make_unique<SimDevice>(sizedProfile(config, profile), number);
    loadDemoState(*device);
    if (config.fill > 0) fillBenchmarkCams(*device, config.fill);
    if (config.users >= 0) fillUsers(*device, config.users);
    return device;
}

}  // namespace

std::unique_ptr<SimLine> makeSimLine(const SimPortConfig& config, const SimProfile& profile) {
    auto line = std::make_unique<SimLine>(config.effectiveFraming());
    for (int number : config.devices) line->addDevice(makeDevice(config, profile, number));
    line->setFaults(config.faults);
    for (int number : config.deadDevices) line->injections().setDead(number, true);
    return line;
}

std::unique_ptr<SimCamConEndpoint> makeSimEndpoint(const SimPortConfig& config,
                                                   const SimProfile& profile) {
    if (config.camBus) {
        std::vector<std::unique_ptr<SimDevice>> devices;
        for (int number : config.devices) devices.push_back(makeDevice(config, profile, number));
        SimCamBusLine::Setup setup;
        setup.baud = config.baud;
        setup.displays = config.displays;
        setup.pcAnswerMs = config.pcAnswerMs;
        setup.silentFromMs = config.silentAfterMs;
        setup.reinitAtMs = config.reinitAfterMs;
        setup.silent = config.deadDevices;
        if (config.faults.dead) setup.silent = config.devices;
        setup.faults.damageBlock = config.faults.corruptProbability;
        setup.faults.loseAck = config.faults.dropProbability;
        setup.faults.seed = config.faults.seed;
        return std::make_unique<SimCamBusLine>(std::move(devices), setup, 0);
    }
    if (!config.tableVariant) return makeSimLine(config, profile);
    auto line = std::make_unique<SimTableLine>(
        *config.tableVariant, makeDevice(config, profile, config.devices.value(0)));
    line->setFaults(config.faults);
    return line;
}

}  // namespace cambench::comm
