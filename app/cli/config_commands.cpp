// settings read/write and plc read/write: JSON files.
#include "cli_output.h"
#include "commands.h"
#include "exit_codes.h"

#include "model/camcon/data_validation.h"
#include "model/json_file.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace cambench::cli {

namespace {

using comm::CamConDevice;
using comm::JobContext;

const JsonFileType kSettingsFile{"cambench-settings", 1, "settings file"};
const JsonFileType kPlcFile{"cambench-plc", 1, "PLC file"};

// PLC areas in file order, with the setting that says how many networks
// each has on this device.
struct PlcArea {
    int area;
    const char* letter;
    const char* countKey;
};
const PlcArea kPlcAreas[] = {
    {PlcNetwork::O, "O", "plcOutputs"},
    {PlcNetwork::P, "P", "inputCount"},
    {PlcNetwork::M, "M", "plcFlags"},
    {PlcNetwork::X, "X", "plcXFlags"},
};

Error fileError(const QString& path, const QString& what) {
    return Error::invalidData(QStringLiteral("%1: %2; fix the file and run the command again "
                                             "(the device was not changed)")
                                  .arg(path, what));
}

Result<QJsonObject> loadJsonFile(const QString& path, const JsonFileType& type) {
    const Result<QByteArray> bytes = readInputFile(path);
    if (!bytes) return bytes.error();
    Result<QJsonObject> root = parseJsonFile(*bytes, type);
    if (!root) return fileError(path, root.error().message);
    return root;
}

// A whole number from JSON, which stores every number as a double.
bool wholeNumber(const QJsonValue& value, qint64* out) {
    if (!value.isDouble()) return false;
    const double d = value.toDouble();
    if (std::floor(d) != d || std::fabs(d) > 9.0e15) return false;
    *out = qint64(d);
    return true;
}

Result<SystemSettings> settingsFromFile(const QString& path) {
    const Result<QJsonObject> root = loadJsonFile(path, kSettingsFile);
    if (!root) return root.error();
    const QJsonObject object = root->value(QStringLiteral("settings")).toObject();
    SystemSettings settings;
    for (auto it = object.begin(); it != object.end(); ++it) {
        const SettingSpec* spec = findSetting(it.key());
        if (!spec) return fileError(path, QStringLiteral("\"%1\" is no setting").arg(it.key()));
        qint64 number = 0;
        if (spec->kind == SettingKind::Text && it.value().isString()) {
            settings.insert(it.key(), it.value().toString());
        } else if (spec->kind != SettingKind::Text && wholeNumber(it.value(), &number)) {
            settings.insert(it.key(), number);
        } else {
            return fileError(path, QStringLiteral("\"%1\" must be %2")
                                       .arg(it.key(), spec->kind == SettingKind::Text
                                                          ? QStringLiteral("a text")
                                                          : QStringLiteral("a whole number")));
        }
    }
    return settings;
}

QByteArray settingsToFile(const SystemSettings& settings) {
    QJsonObject values;
    for (auto it = settings.begin(); it != settings.end(); ++it) {
        values.insert(it.key(), QJsonValue::fromVariant(it.value()));
    }
    QJsonObject root = jsonFileHeader(kSettingsFile);
    root.insert(QStringLiteral("settings"), values);
    return toIndentedJson(root);
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
    const Result<Read> read = session.run<Read>(
        QStringLiteral("settings read"), [](CamConDevice& client, JobContext&) -> Result<Read> {
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
    const Status written = writeOutput(*path, settingsToFile(read->settings));
    return written ? ExitOk : reportError(written.error());
}

int writeSettings(CliSession& session, CommandArgs& args) {
    const Result<QString> path = args.takeRequiredPositional(QStringLiteral("a JSON FILE"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<SystemSettings> settings = settingsFromFile(*path);
    if (!settings) return reportError(settings.error());
    const QString file = *path;
    const SystemSettings wanted = *settings;
    const Status written =
        session.run<Done>(QStringLiteral("settings write"),
                          [file, wanted](CamConDevice& client, JobContext&) -> Status {
                              // Only values that differ from the device are written, so only
                              // they must pass validation (a device may hold odd defaults).
                              const Result<SystemSettings> current = client.readSettings();
                              if (!current) return current.error();
                              SystemSettings changed;
                              for (auto it = wanted.begin(); it != wanted.end(); ++it) {
                                  const SettingSpec* spec = findSetting(it.key());
                                  if (spec->readOnly) continue;
                                  if (current->contains(it.key()) &&
                                      current->value(it.key()).toString() == it->toString()) {
                                      continue;
                                  }
                                  changed.insert(it.key(), *it);
                              }
                              const QStringList problems = validateSettings(changed);
                              if (!problems.isEmpty()) return invalidFileError(file, problems);
                              return changed.isEmpty() ? success()
                                                       : client.writeSettings(changed, *current);
                          });
    return written ? ExitOk : reportError(written.error());
}

QJsonObject networkToJson(const PlcNetwork& network, const char* letter) {
    QJsonArray symbols;
    for (quint16 symbol : network.symbols) symbols.append(int(symbol));
    return QJsonObject{{QStringLiteral("area"), QLatin1String(letter)},
                       {QStringLiteral("number"), network.number},
                       {QStringLiteral("value"), network.value},
                       {QStringLiteral("reset"), int(network.reset)},
                       {QStringLiteral("symbols"), symbols}};
}

Result<PlcNetwork> networkFromJson(const QJsonValue& value, int index, const QString& path) {
    const QJsonObject object = value.toObject();
    const QString where = QStringLiteral("network %1").arg(index + 1);
    PlcNetwork network;
    const QString letter = object.value(QStringLiteral("area")).toString();
    const PlcArea* area = nullptr;
    for (const PlcArea& candidate : kPlcAreas) {
        if (letter == QLatin1String(candidate.letter)) area = &candidate;
    }
    if (!area)
        return fileError(path, QStringLiteral("%1: \"area\" must be O, P, M or X").arg(where));
    network.area = area->area;
    qint64 number = 0;
    qint64 setValue = 0;
    qint64 reset = 0;
    if (!wholeNumber(object.value(QStringLiteral("number")), &number) ||
        !wholeNumber(object.value(QStringLiteral("value")), &setValue) ||
        !wholeNumber(object.value(QStringLiteral("reset")), &reset) || reset < 0 ||
        reset > 0xFFFF || setValue < std::numeric_limits<qint32>::min() ||
        setValue > std::numeric_limits<qint32>::max()) {
        return fileError(path, QStringLiteral("%1: \"number\", \"value\" and \"reset\" must be "
                                              "whole numbers (reset 0..65535)")
                                   .arg(where));
    }
    network.number = int(qBound(qint64(-1), number, qint64(1 << 20)));
    network.value = qint32(setValue);
    network.reset = quint16(reset);
    const QJsonArray symbols = object.value(QStringLiteral("symbols")).toArray();
    if (symbols.size() != PlcNetwork::kSymbols) {
        return fileError(path, QStringLiteral("%1: \"symbols\" must list %2 words")
                                   .arg(where)
                                   .arg(PlcNetwork::kSymbols));
    }
    for (int i = 0; i < PlcNetwork::kSymbols; ++i) {
        qint64 word = 0;
        if (!wholeNumber(symbols.at(i), &word) || word < 0 || word > 0xFFFF) {
            return fileError(
                path,
                QStringLiteral("%1: symbol %2 must be a word 0..65535").arg(where).arg(i + 1));
        }
        network.symbols[size_t(i)] = quint16(word);
    }
    return network;
}

int readPlc(CliSession& session, CommandArgs& args) {
    const Result<QString> path =
        args.takeOption(QStringLiteral("--output-file"), QStringLiteral("-o"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    session.setShowProgress(true);
    const Result<QJsonArray> networks = session.run<QJsonArray>(
        QStringLiteral("plc read"),
        [](CamConDevice& client, JobContext& job) -> Result<QJsonArray> {
            QList<int> counts;
            int total = 0;
            for (const PlcArea& area : kPlcAreas) {
                const Result<QVariant> count = client.readSetting(QLatin1String(area.countKey));
                if (!count) return count.error();
                counts.append(
                    int(qBound(qint64(0), count->toLongLong(), qint64(kMaxPlcNumber + 1))));
                total += counts.last();
            }
            QJsonArray result;
            int done = 0;
            for (int a = 0; a < int(std::size(kPlcAreas)); ++a) {
                for (int number = 0; number < counts.at(a); ++number) {
                    job.progress(done++, total, QStringLiteral("reading PLC networks"));
                    const Result<PlcNetwork> network =
                        client.readPlcNetwork(kPlcAreas[a].area, number);
                    if (!network) return network.error();
                    // Empty networks are the default; the file lists the used ones.
                    if (!network->isEmpty())
                        result.append(networkToJson(*network, kPlcAreas[a].letter));
                }
            }
            return result;
        });
    if (!networks) return reportError(networks.error());
    QJsonObject root = jsonFileHeader(kPlcFile);
    root.insert(QStringLiteral("networks"), *networks);
    const Status written = writeOutput(*path, toIndentedJson(root));
    return written ? ExitOk : reportError(written.error());
}

int writePlc(CliSession& session, CommandArgs& args) {
    const Result<QString> path = args.takeRequiredPositional(QStringLiteral("a JSON FILE"));
    if (!path) return reportError(path.error());
    if (const Status done = args.finish(); !done) return reportError(done.error());
    const Result<QJsonObject> root = loadJsonFile(*path, kPlcFile);
    if (!root) return reportError(root.error());
    const QJsonArray array = root->value(QStringLiteral("networks")).toArray();
    QList<PlcNetwork> networks;
    QStringList problems;
    for (int i = 0; i < array.size(); ++i) {
        const Result<PlcNetwork> network = networkFromJson(array.at(i), i, *path);
        if (!network) return reportError(network.error());
        problems += validatePlcNetwork(*network);
        networks.append(*network);
    }
    if (!problems.isEmpty()) return reportError(invalidFileError(*path, problems));
    session.setShowProgress(true);
    const Status written = session.run<Done>(
        QStringLiteral("plc write"), [networks](CamConDevice& client, JobContext& job) -> Status {
            for (int i = 0; i < networks.size(); ++i) {
                job.progress(i, networks.size(), QStringLiteral("writing PLC networks"));
                if (const Status ok = client.writePlcNetwork(networks.at(i)); !ok) return ok;
            }
            return success();
        });
    return written ? ExitOk : reportError(written.error());
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
