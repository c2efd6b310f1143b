#include "sim_machine.h"

#include "sim_options.h"

#include "comm/device/family_registry.h"
#include "comm/device/protocol_registry.h"
#include "comm/sim/sim_pty_server.h"
#include "comm/sim/sim_tcp_server.h"
#include "model/machine/machine_file.h"

#include <QFile>

namespace cambench {

using namespace comm;

namespace {

// Whether the family's simulator has an option of this name.
bool hasOption(const SimulatorInfo& simulator, const QString& name) {
    for (const QCommandLineOption& option : simulator.options())
        if (option.names().contains(name)) return true;
    return false;
}

// The simulated line of one device, read as cambench-sim reads its own
// options; an error without the device's name (the caller adds it).
Result<SimulatedLine> deviceLine(const MachineDevice& device, const SimHostOptions& shared) {
    const Result<const FamilyInfo*> family = FamilyRegistry::instance().usable(device.family);
    if (!family) return Error::usage(family.error().message);
    const SimulatorInfo* simulator = SimulatorRegistry::instance().find((*family)->id);
    if (!simulator)
        return Error::usage(QStringLiteral("no simulator of family %1 is built into this CamBench")
                                .arg((*family)->id));
    SimHostOptions options = shared;
    options.protocol = device.option(QStringLiteral("protocol"));
    if (!options.protocol.isEmpty()) {
        const ProtocolInfo* protocol = ProtocolRegistry::instance().find(options.protocol);
        if (!protocol || protocol->familyId != (*family)->id)
            return Error::usage(QStringLiteral("\"protocol\": \"%1\" is not a protocol of family "
                                               "%2 (cambench-sim --help lists them)")
                                    .arg(options.protocol, (*family)->id));
    }
    QStringList args{QStringLiteral("cambench-sim")};
    for (const auto& [key, value] : device.options) {
        // Where the real device is does not matter here; the protocol is
        // the shared option read above.
        if (key == QLatin1String("port") || key == QLatin1String("protocol")) continue;
        if (!hasOption(*simulator, key))
            return Error::usage(QStringLiteral("\"%1\" is not an option of the %2 simulator "
                                               "(cambench-sim --help lists them)")
                                    .arg(key, (*family)->id));
        args << QStringLiteral("--") + key << value;
    }
    QCommandLineParser parser;
    addSimOptions(parser);
    if (!parser.parse(args)) return Error::usage(parser.errorText());
    return simulator->fromOptions(parser, options);
}

// The file's shaft: `from`'s axis drives, `to`'s position follows.
Status coupleShaft(const MachineFile& file, const QList<SimulatedLine*>& lines,
                   const std::shared_ptr<SimShaft>& shaft, const QString& where) {
    int from = -1;
    int to = -1;
    for (int i = 0; i < file.devices.size(); ++i) {
        if (file.devices.at(i).name == file.shaftFrom) from = i;
        if (file.devices.at(i).name == file.shaftTo) to = i;
    }
    const auto label = [&](int i) { return machineDeviceLabel(i, file.devices.at(i).name); };
    Status coupled =
        driveShaft(lines.at(from)->shaft, shaft, file.shaftAxis.value_or(1), label(from));
    if (coupled)
        coupled = followShaft(lines.at(to)->shaft, shaft,
                              file.shaftPerTurn.value_or(kSimShaftPerTurn), label(to));
    if (!coupled)
        return Error::usage(
            QStringLiteral("Machine file %1: the shaft: %2").arg(where, coupled.error().message));
    return success();
}

}  // namespace

SimMachine::~SimMachine() = default;

Result<std::unique_ptr<SimMachine>> SimMachine::build(const QString& path,
                                                      const SimHostOptions& shared) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return Error::usage(
            QStringLiteral("cannot read the machine file %1: %2").arg(path, file.errorString()));
    const Result<MachineFile> machine = parseMachineFile(file.readAll(), path);
    if (!machine) return machine.error();
    std::unique_ptr<SimMachine> built(new SimMachine);
    QList<SimulatedLine*> lines;
    built->m_lines.reserve(machine->devices.size());
    for (int i = 0; i < machine->devices.size(); ++i) {
        const MachineDevice& device = machine->devices.at(i);
        Result<SimulatedLine> line = deviceLine(device, shared);
        if (!line)
            return Error::usage(
                QStringLiteral("Machine file %1, %2: %3")
                    .arg(path, machineDeviceLabel(i, device.name), line.error().message));
        built->m_names << device.name;
        built->m_lines.push_back(std::move(line).value());
        lines << &built->m_lines.back();
    }
    if (!machine->shaftFrom.isEmpty()) {
        built->m_shaft = std::make_shared<SimShaft>();
        if (const Status coupled = coupleShaft(*machine, lines, built->m_shaft, path); !coupled)
            return coupled.error();
    }
    return built;
}

Result<QStringList> SimMachine::serve(std::optional<quint16> tcpBase) {
    QStringList served;
    if (tcpBase && *tcpBase != 0 && *tcpBase + m_lines.size() - 1 > 65535)
        return Error::usage(QStringLiteral("--tcp %1: the machine's %2 devices need ports up to "
                                           "%3; give a lower first port.")
                                .arg(*tcpBase)
                                .arg(m_lines.size())
                                .arg(*tcpBase + m_lines.size() - 1));
    for (size_t i = 0; i < m_lines.size(); ++i) {
        SimulatedLine& line = m_lines.at(i);
        const QString& name = m_names.at(qsizetype(i));
        if (tcpBase) {
            auto tcp = std::make_unique<SimTcpServer>(*line.endpoint, line.pacer);
            const quint16 port = *tcpBase == 0 ? 0 : quint16(*tcpBase + i);
            if (const Status listening = tcp->listen(port); !listening)
                return Error::communication(
                    QStringLiteral("%1: %2").arg(name, listening.error().message));
            served << QStringLiteral("%1 tcp://127.0.0.1:%2").arg(name).arg(tcp->port());
            m_servers.push_back(std::move(tcp));
        } else {
            auto pty = std::make_unique<SimPtyServer>(*line.endpoint, line.pacer);
            if (const Status opened = pty->open(); !opened)
                return Error::communication(
                    QStringLiteral("%1: %2").arg(name, opened.error().message));
            served << QStringLiteral("%1 %2").arg(name, pty->slavePath());
            m_servers.push_back(std::move(pty));
        }
    }
    return served;
}

}  // namespace cambench
