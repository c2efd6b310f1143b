// settings read/write and plc read/write: JSON files (model/camcon/settings_file.h,
// plc_file.h), written through the one write path.
#include "app/cli/camcon/camcon_commands.h"
#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"
#include "write_output.h"

#include "comm/camcon/usecases/read_everything.h"
#include "model/camcon/plc_file.h"
#include "model/camcon/settings_file.h"

namespace cambench::cli {

namespace {

using comm::CamConDevice;
using comm::JobContext;

// A file that cannot be loaded: the device was not touched.
Error fileError(const Error& error) {
    Error result = error;
    result.message += QStringLiteral(
        " Fix the file and run the command again (the device was not "
        "changed).");
    return result;
}

int readSettings(CliSession& session, CommandArgs& args) {
    const Result<QString> path =
        args.takeOption(QStringLiteral("--output-file"), QStringLiteral("-o"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    struct Read {
        SystemSettings settings;
        QStringList skipped;
    };
    const Result<Read> read = runOnCamCon<Read>(
        session, QStringLiteral("settings read"),
        [](CamConDevice& client, JobContext&) -> Result<Read> {
            Read result;
            Result<SystemSettings> settings = client.readSettings(&result.skipped);
            if (!settings) return settings.error();
            result.settings = std::move(settings).value();
            return result;
        });
    if (!read) return reportError(read.error());
    for (const QString& skipped : read->skipped) {
        printError(
            QStringLiteral("note: the device does not know %1; left out of the file").arg(skipped));
    }
    const Status written = writeOutput(*path, settingsFileToJson(read->settings));
    return written ? ExitOk : reportError(written.error());
}

int writeSettings(CliSession& session, CommandArgs& args) {
    const Result<QString> path = args.takeRequiredPositional(QStringLiteral("a JSON FILE"));
    if (!path) return reportError(path.error());
    const Result<QStringList> link = takeCommunicationSettings(args);
    if (!link) return reportError(link.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<SystemSettings> settings = loadSettingsFile(*path);
    if (!settings) return reportError(fileError(settings.error()));
    const SystemSettings wanted = *settings;
    const QStringList asked = *link;
    // Read once; the same values serve as the device's for the write.
    return runWritePlan(
        session, QStringLiteral("settings write"),
        [wanted, asked](CamConDevice& device, const DeviceInfo&) -> Result<usecases::WritePlan> {
            Result<SystemSettings> onDevice = device.readSettings();
            if (!onDevice) return onDevice.error();
            usecases::WritePlan plan;
            plan.settings = usecases::settingsGroups(wanted);
            plan.settingsOnDevice = *onDevice;
            plan.linkSettingsAsked = asked;
            return plan;
        });
}

int readPlc(CliSession& session, CommandArgs& args) {
    const Result<QString> path =
        args.takeOption(QStringLiteral("--output-file"), QStringLiteral("-o"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    session.setShowProgress(true);
    const Result<QList<PlcNetwork>> networks = runOnCamCon<QList<PlcNetwork>>(
        session, QStringLiteral("plc read"),
        [](CamConDevice& client, JobContext& job) -> Result<QList<PlcNetwork>> {
            if (!client.has(comm::CamConCapability::PlcNetworks))
                return client.missing(comm::CamConCapability::PlcNetworks);
            // The counts of the networks per area are settings.
            SystemSettings counts;
            for (const char* key : {"plcOutputs", "inputCount", "plcFlags", "plcXFlags"}) {
                const Result<QVariant> count = client.readSetting(QLatin1String(key));
                if (!count) return count.error();
                counts.insert(QLatin1String(key), *count);
            }
            const QMap<int, int> perArea = usecases::plcNetworkCounts(counts);
            int total = 0;
            for (const int count : perArea) total += count;
            QList<PlcNetwork> result;
            int done = 0;
            for (auto it = perArea.cbegin(); it != perArea.cend(); ++it) {
                for (int number = 0; number < *it; ++number) {
                    job.progress(done++, total, QStringLiteral("reading PLC networks"));
                    const Result<PlcNetwork> network = client.readPlcNetwork(it.key(), number);
                    if (!network) return network.error();
                    // Empty networks are the default; the file lists the used ones.
                    if (!network->isEmpty()) result << *network;
                }
            }
            return result;
        });
    if (!networks) return reportError(networks.error());
    const Status written = writeOutput(*path, plcFileToJson(*networks));
    return written ? ExitOk : reportError(written.error());
}

int writePlc(CliSession& session, CommandArgs& args) {
    const Result<QString> path = args.takeRequiredPositional(QStringLiteral("a JSON FILE"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<QList<PlcNetwork>> networks = loadPlcFile(*path);
    if (!networks) return reportError(fileError(networks.error()));
    usecases::WritePlan plan;
    for (const PlcNetwork& network : *networks) plan.plcNetworks << usecases::PlcWrite{network, {}};
    return runWritePlan(session, QStringLiteral("plc write"), plan);
}

}  // namespace

int runSettings(CliSession& session, CommandArgs& args) {
    const Result<QString> verb = takeVerb(args, {QStringLiteral("read"), QStringLiteral("write")});
    if (!verb) return reportError(verb.error());
    return *verb == QLatin1String("read") ? readSettings(session, args)
                                          : writeSettings(session, args);
}

int runPlc(CliSession& session, CommandArgs& args) {
    const Result<QString> verb = takeVerb(args, {QStringLiteral("read"), QStringLiteral("write")});
    if (!verb) return reportError(verb.error());
    return *verb == QLatin1String("read") ? readPlc(session, args) : writePlc(session, args);
}

}  // namespace cambench::cli
