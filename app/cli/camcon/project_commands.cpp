// project read / project write: the whole device as one project file, on
// the read-everything use case and the one write path.
#include "app/cli/camcon/camcon_commands.h"
#include "app/cli/cli_output.h"
#include "app/cli/exit_codes.h"
#include "write_output.h"

#include "comm/camcon/usecases/read_everything.h"
#include "model/camcon/project_file.h"

namespace cambench::cli {

namespace {

using comm::CamConDevice;
using comm::JobContext;
using usecases::UseCaseProgress;

// Problems of the device's own values are noted, never refused.
constexpr int kNotedWarnings = 5;

int readProject(CliSession& session, CommandArgs& args) {
    ProjectSaveOptions options;
    options.includeUserNumbers = args.takeFlag(QStringLiteral("--with-user-numbers"));
    const Result<QString> path =
        args.takeOption(QStringLiteral("--output-file"), QStringLiteral("-o"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    session.setShowProgress(true);
    const Result<usecases::ReadEverything> read = runOnCamCon<usecases::ReadEverything>(
        session, QStringLiteral("project read"),
        [](CamConDevice& device, JobContext& job) -> Result<usecases::ReadEverything> {
            const Result<DeviceInfo> info = device.readInfo();
            if (!info) return info.error();
            return usecases::readEverything(device, *info, UseCaseProgress::of(job));
        });
    if (!read) return reportError(read.error());
    for (const QString& skipped : read->skipped)
        printError(QStringLiteral("note: %1").arg(skipped));
    const QStringList warnings = validateProject(read->project);
    for (int i = 0; i < warnings.size() && i < kNotedWarnings; ++i)
        printError(QStringLiteral("note: the device holds a value outside the manual's limits: %1")
                       .arg(warnings.at(i)));
    if (warnings.size() > kNotedWarnings)
        printError(
            QStringLiteral("note: and %1 more such values").arg(warnings.size() - kNotedWarnings));
    const Status written = writeOutput(*path, projectToJson(read->project, options));
    return written ? ExitOk : reportError(written.error());
}

int writeProject(CliSession& session, CommandArgs& args) {
    const Result<QString> path = args.takeRequiredPositional(QStringLiteral("a project FILE"));
    if (!path) return reportError(path.error());
    const Result<QStringList> link = takeCommunicationSettings(args);
    if (!link) return reportError(link.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<Project> wanted = loadProject(*path);
    if (!wanted) return reportError(wanted.error());
    const Project project = *wanted;
    const QStringList asked = *link;
    return runWritePlan(
        session, QStringLiteral("project write"),
        [project, asked](CamConDevice& device,
                         const DeviceInfo& info) -> Result<usecases::WritePlan> {
            // What the plan needs to know of the device: its outputs (every
            // program of the project replaces the whole program), the
            // settings (written against them) and the users (matched by
            // number or name). The rest is read item by item as it is written.
            Project onDevice;
            onDevice.device = info;
            onDevice.readAt.parts.insert(ProjectPart::Device, QDateTime::currentDateTimeUtc());
            Result<SystemSettings> settings = device.readSettings();
            if (!settings) return settings.error();
            onDevice.settings = *settings;
            onDevice.readAt.parts.insert(ProjectPart::Settings, QDateTime::currentDateTimeUtc());
            if (!project.users.isEmpty() && device.has(comm::CamConCapability::Users)) {
                Result<QList<User>> users = device.readUsers();
                if (!users) return users.error();
                onDevice.users = *users;
                onDevice.readAt.parts.insert(ProjectPart::Users, QDateTime::currentDateTimeUtc());
            }
            usecases::WritePlan plan = usecases::planFromProject(project, onDevice);
            plan.linkSettingsAsked = asked;
            return plan;
        });
}

}  // namespace

int runProject(CliSession& session, CommandArgs& args) {
    const Result<QString> verb = takeVerb(args, {QStringLiteral("read"), QStringLiteral("write")});
    if (!verb) return reportError(verb.error());
    return *verb == QLatin1String("read") ? readProject(session, args)
                                          : writeProject(session, args);
}

}  // namespace cambench::cli
