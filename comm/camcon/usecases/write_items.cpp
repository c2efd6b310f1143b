#include "write_items.h"

#include <QCoreApplication>

#include "plan_check.h"
#include "read_everything.h"
#include "value_text.h"

#include "model/camcon/cam_validation.h"
#include "model/camcon/link_settings.h"

#include <functional>

namespace cambench::usecases {

namespace {

using comm::CamConCapability;
using comm::CamConDevice;

constexpr int kUserAccessOutputs = 256;

// How to read, write and compare one kind of value.
template <class T>
struct ValueOps {
    std::function<Result<T>()> read;
    std::function<Status(const T& before)> write;
    std::function<bool(const T&, const T&)> same;
    std::function<QString(const T&)> text;
};

bool stopsTheRun(const Error& error) {
    return error.kind == ErrorKind::Communication || error.kind == ErrorKind::Cancelled;
}

Track normalised(Track track) {
    normaliseTrack(track);
    return track;
}

bool sameCams(const Track& a, const Track& b) {
    return normalised(a).cams == normalised(b).cams;
}

// Numbers as qint64, texts as QString: values read and values loaded from
// files compare equal when they mean the same.
QVariant canonical(const QString& key, const QVariant& value) {
    const SettingSpec* spec = findSetting(key);
    if (spec && spec->kind == SettingKind::Text) return value.toString();
    return value.toLongLong();
}

// The values of `settings` for the keys of `keys` that it has.
SystemSettings onlyKeys(const SystemSettings& settings, const SystemSettings& keys) {
    SystemSettings result;
    for (auto it = keys.cbegin(); it != keys.cend(); ++it) {
        if (settings.contains(it.key()))
            result.insert(it.key(), canonical(it.key(), settings.value(it.key())));
    }
    return result;
}

bool sameSettings(const SystemSettings& a, const SystemSettings& b) {
    return onlyKeys(a, a) == onlyKeys(b, b);
}

User withFullAccess(User user) {
    while (user.outputAccess.size() < kUserAccessOutputs) user.outputAccess.append(false);
    return user;
}

bool sameUser(const std::optional<User>& a, const std::optional<User>& b) {
    if (!a || !b) return !a && !b;
    return withFullAccess(*a) == withFullAccess(*b);
}

const User* findUser(const QList<User>& users, const QString& number) {
    if (number.isEmpty()) return nullptr;
    for (const User& user : users) {
        if (user.number == number) return &user;
    }
    return nullptr;
}

// Resolves users without a number (projects saved without them): they keep
// the number of the device's user with the same name.
void resolveUserNumbers(WritePlan& plan) {
    const QList<User>& onDevice = *plan.usersOnDevice;
    for (UserWrite& write : plan.users) {
        if (!write.wanted || !write.wanted->number.isEmpty()) continue;
        const User* named = nullptr;
        if (const User* byNumber = findUser(onDevice, write.deviceNumber)) named = byNumber;
        for (const User& user : onDevice) {
            if (!named && user.name == write.wanted->name) named = &user;
        }
        if (!named) continue;  // the check refuses it
        write.wanted->number = named->number;
        if (write.deviceNumber.isEmpty()) write.deviceNumber = named->number;
    }
}

// The communication settings of a plan's settings groups, taken out of
// them: those asked for by name, one group each in the order they are
// sent, and the others, left out (only those that differ from the device's
// are worth naming).
struct LinkSettings {
    QList<SettingsWrite> asked;
    SystemSettings leftOut;
};

LinkSettings takeLinkSettings(WritePlan& plan) {
    LinkSettings link;
    SystemSettings asked;
    QString group;
    for (SettingsWrite& write : plan.settings) {
        for (const QString& key : linkSettingKeys()) {
            if (!write.wanted.contains(key)) continue;
            const QVariant value = write.wanted.take(key);
            group = write.group;
            if (plan.linkSettingsAsked.contains(key)) {
                asked.insert(key, value);
                continue;
            }
            const bool same =
                plan.settingsOnDevice && plan.settingsOnDevice->contains(key) &&
                canonical(key, plan.settingsOnDevice->value(key)) == canonical(key, value);
            if (!same) link.leftOut.insert(key, value);
        }
    }
    plan.settings.removeIf([](const SettingsWrite& write) { return write.wanted.isEmpty(); });
    for (const QString& key : linkSettingKeys()) {
        if (asked.contains(key)) link.asked << SettingsWrite{group, {{key, asked.value(key)}}};
    }
    return link;
}

QString leftOutNote(const SystemSettings& leftOut, const SystemSettings& onDevice) {
    SystemSettings device;
    for (auto it = leftOut.cbegin(); it != leftOut.cend(); ++it) {
        if (onDevice.contains(it.key())) device.insert(it.key(), onDevice.value(it.key()));
    }
    return QCoreApplication::translate(
               "cambench::usecases",
               "Communication settings left out: %1 (the device keeps %2). They decide how the "
               "device is reached and are written only when asked for by name.")
        .arg(linkSettingsText(leftOut),
             device.isEmpty() ? QCoreApplication::translate("cambench::usecases", "its own")
                              : linkSettingsText(device));
}

class Writer {
public:
    Writer(CamConDevice& connection, const WritePlan& plan, const LinkSettings& link,
           const UseCaseProgress& progress)
        : m_connection(connection),
          m_plan(plan),
          m_link(link),
          m_progress(progress),
          m_settings(plan.settingsOnDevice.value_or(SystemSettings())),
          m_users(plan.usersOnDevice.value_or(QList<User>())) {}

    WriteReport run() {
        WriteReport report;
        m_total = m_plan.itemCount() + m_link.asked.size();
        readEepromLockFirst();
        // An unlock first, so that everything after it is stored.
        report.eepromLockFirst = m_plan.eepromLock && !m_plan.eepromLock->wanted;
        if (report.eepromLockFirst) report.eepromLock = writeEepromLock(*m_plan.eepromLock);
        for (const SettingsWrite& group : m_plan.settings) report.settings << writeSettings(group);
        for (const NameWrite& name : m_plan.programNames)
            report.programNames << keyed(programNameItem(name), writeName(name, true));
        const std::optional<ProgrammingProgram> programming = programmingBeforeTracks();
        for (const TrackWrite& track : m_plan.tracks)
            report.tracks << keyed(itemOf(track), writeTrack(track));
        if (programming && setProgrammingProgramBack(*programming, report))
            m_programmingAtStart = programming;
        fillDeadTimeBeliefs();
        for (const DeadTimeWrite& deadTime : m_plan.deadTimes)
            report.deadTimes << keyed(itemOf(deadTime), writeDeadTime(deadTime));
        fillDeadTimeModeBeliefs();
        for (const DeadTimeModeWrite& mode : m_plan.deadTimeModes)
            report.deadTimeModes << keyed(itemOf(mode), writeDeadTimeMode(mode));
        for (const NameWrite& name : m_plan.outputNames)
            report.outputNames << keyed(outputNameItem(name), writeName(name, false));
        for (const UserWrite& user : m_plan.users)
            report.users << keyed(itemOf(user), writeUser(user));
        for (const PlcWrite& network : m_plan.plcNetworks)
            report.plcNetworks << keyed(itemOf(network), writePlcNetwork(network));
        for (const AnalogueCamWrite& track : m_plan.analogueCams)
            report.analogueCams << keyed(itemOf(track), writeAnalogueCams(track));
        if (m_plan.programmingProgram)
            report.programmingProgram = writeProgrammingProgram(*m_plan.programmingProgram);
        // A lock last, so that everything before it is stored first.
        if (m_plan.eepromLock && !report.eepromLockFirst)
            report.eepromLock = writeEepromLock(*m_plan.eepromLock);
        // Last of all: after them this connection may not reach the device.
        for (const SettingsWrite& link : m_link.asked) report.linkSettings << writeLink(link);
        if (const QString note = eepromNote(report); !note.isEmpty()) report.notes << note;
        report.linkSettingsLeftOut = m_link.leftOut;
        if (!m_link.leftOut.isEmpty()) report.notes << leftOutNote(m_link.leftOut, m_settings);
        if (const QString note = linkWrittenNote(report); !note.isEmpty()) report.notes << note;
        m_progress.report(m_total, m_total,
                          QCoreApplication::translate("cambench::usecases", "written"));
        return report;
    }

private:
    // The common course of one item: belief or read, compare, write, and
    // after a failure read back and tell the state as it is.
    template <class T>
    ItemOutcome<T> writeItem(const QString& label, const T& wanted, std::optional<T> before,
                             const ValueOps<T>& ops) {
        ItemOutcome<T> outcome;
        outcome.label = label;
        m_progress.report(m_done++, m_total, label);
        if (m_progress.cancelled() && !m_stop) m_stop = Error::cancelled();
        if (m_stop) {
            outcome.error = *m_stop;
            return outcome;  // NotSent
        }
        if (!before) {
            const Result<T> read = ops.read();
            if (!read) {
                outcome.error = inContext(QCoreApplication::translate(
                                              "cambench::usecases", "reading it before the write"),
                                          read.error());
                if (stopsTheRun(read.error())) stopAfter(label, read.error());
                return outcome;  // NotSent: nothing was written
            }
            before = *read;
        }
        if (ops.same(*before, wanted)) {
            outcome.state = WriteState::Unchanged;
            outcome.actual = wanted;
            outcome.actualText = ops.text(wanted);
            return outcome;
        }
        const Status written = ops.write(*before);
        if (written) {
            outcome.state = WriteState::Written;
            outcome.actual = wanted;
            outcome.actualText = ops.text(wanted);
            return outcome;
        }
        outcome.error = written.error();
        if (written.error().kind == ErrorKind::NotUnderstood) {
            // ":Z": the device does not know the command, so it did nothing.
            outcome.state = WriteState::Failed;
            outcome.actual = *before;
            outcome.actualText = ops.text(*before);
            return outcome;
        }
        const Result<T> after = ops.read();
        if (!after) {
            outcome.state = WriteState::Unknown;
            outcome.error.message +=
                QCoreApplication::translate("cambench::usecases", " Reading it back failed too: %1")
                    .arg(after.error().message);
            if (stopsTheRun(after.error())) stopAfter(label, after.error());
            return outcome;
        }
        outcome.actual = *after;
        outcome.actualText = ops.text(*after);
        if (ops.same(*after, *before)) {
            outcome.state = WriteState::Failed;
        } else if (ops.same(*after, wanted)) {
            // The reply said no (or was lost), the device says yes.
            outcome.state = WriteState::Written;
            outcome.note = QCoreApplication::translate("cambench::usecases",
                                                       "read back after the error \"%1\"")
                               .arg(outcome.error.message);
            outcome.error = Error();
        } else {
            outcome.state = WriteState::ChangedThoughFailed;
            outcome.actualText += QCoreApplication::translate("cambench::usecases", " (before: %1)")
                                      .arg(ops.text(*before));
        }
        return outcome;
    }

    void stopAfter(const QString& label, const Error& error) {
        if (error.kind == ErrorKind::Cancelled) {
            m_stop = Error::cancelled();
            return;
        }
        m_stop = Error{error.kind,
                       QCoreApplication::translate(
                           "cambench::usecases",
                           "not sent: the connection failed at %1; nothing after it was "
                           "sent")
                           .arg(label),
                       0};
    }

    static Error inContext(const QString& step, const Error& error) {
        Error result = error;
        result.message = QStringLiteral("%1: %2").arg(step, error.message);
        return result;
    }

    ItemOutcome<SystemSettings> writeSettings(const SettingsWrite& group) {
        ValueOps<SystemSettings> ops;
        const SystemSettings keys = group.wanted;
        ops.read = [this, keys]() -> Result<SystemSettings> {
            Result<SystemSettings> read = m_connection.readSettings();
            if (!read) return read.error();
            m_settings = *read;
            return onlyKeys(*read, keys);
        };
        ops.write = [this, &group](const SystemSettings&) -> Status {
            const Status written = m_connection.writeSettings(group.wanted, m_settings);
            if (written) {
                for (auto it = group.wanted.cbegin(); it != group.wanted.cend(); ++it)
                    m_settings.insert(it.key(), *it);
            }
            return written;
        };
        ops.same = sameSettings;
        ops.text = settingsText;
        return writeItem<SystemSettings>(settingsLabel(group.group, group.wanted), group.wanted,
                                         onlyKeys(m_settings, keys), ops);
    }

    // A communication setting asked for by name. Once the device number is
    // written, a bus protocol addresses the device by its new number.
    ItemOutcome<SystemSettings> writeLink(const SettingsWrite& link) {
        ItemOutcome<SystemSettings> outcome = writeSettings(link);
        const QString key = link.wanted.firstKey();
        if (key == QLatin1String("deviceNumber") && outcome.state == WriteState::Written)
            m_connection.setDevice(int(link.wanted.first().toLongLong()));
        return outcome;
    }

    // What the next connection needs once communication settings were
    // written (or may have been).
    static QString linkWrittenNote(const WriteReport& report) {
        SystemSettings written;
        bool uncertain = false;
        for (const auto& outcome : report.linkSettings) {
            if (outcome.state == WriteState::Written) {
                for (auto it = outcome.actual->cbegin(); it != outcome.actual->cend(); ++it)
                    written.insert(it.key(), *it);
            }
            uncertain = uncertain || outcome.state == WriteState::Unknown ||
                        outcome.state == WriteState::ChangedThoughFailed;
        }
        if (written.isEmpty() && !uncertain) return {};
        if (written.isEmpty())
            return QCoreApplication::translate(
                "cambench::usecases",
                "Whether the communication settings changed is not known: if the next "
                "connection fails, try the settings that were to be written.");
        return QCoreApplication::translate("cambench::usecases",
                                           "Communication settings written: the next connection "
                                           "to this device needs %1.")
            .arg(linkSettingsText(written));
    }

    // Program names (0-based) and output names (1-based) take the same course.
    ItemOutcome<QString> writeName(const NameWrite& name, bool program) {
        ValueOps<QString> ops;
        ops.read = [this, &name, program] {
            return program ? m_connection.readProgramName(name.number)
                           : m_connection.readOutputName(name.number);
        };
        ops.write = [this, &name, program](const QString&) {
            return program ? m_connection.writeProgramName(name.number, name.wanted)
                           : m_connection.writeOutputName(name.number, name.wanted);
        };
        ops.same = [](const QString& a, const QString& b) { return a == b; };
        ops.text = nameText;
        const QString label =
            program ? programNameLabel(name.number) : outputNameLabel(name.number);
        return writeItem<QString>(label, name.wanted, name.believed, ops);
    }

    ItemOutcome<Track> writeTrack(const TrackWrite& write) {
        const int output = write.wanted.output;
        std::optional<Track> found;  // the track as read before the write
        ValueOps<Track> ops;
        ops.read = [this, &write, output, &found]() -> Result<Track> {
            Result<Track> read = m_connection.readTrack(write.program, output);
            if (read && !found) found = *read;
            return read;
        };
        ops.write = [this, &write](const Track& before) {
            return m_connection.writeTrackFrom(write.program, write.wanted, before);
        };
        ops.same = sameCams;
        ops.text = [](const Track& track) { return camsText(normalised(track)); };
        // Always read first: the differing cams are what is sent.
        ItemOutcome<Track> outcome =
            writeItem<Track>(trackLabel(write.program, output), write.wanted, std::nullopt, ops);
        if (write.believed && found && !sameCams(*write.believed, *found)) {
            // Changed on the device since the caller read it: say so.
            const QString note =
                QCoreApplication::translate("cambench::usecases",
                                            "the device held %1, not %2 as last read")
                    .arg(camsText(normalised(*found)), camsText(normalised(*write.believed)));
            outcome.note =
                outcome.note.isEmpty() ? note : outcome.note + QStringLiteral("; ") + note;
        }
        return outcome;
    }

    // Dead times are read for all outputs up to the highest one at once:
    // the device has no cheaper way to read one of them.
    void fillDeadTimeBeliefs() {
        int highest = 0;
        for (const DeadTimeWrite& write : m_plan.deadTimes) {
            if (!write.believed) highest = std::max(highest, write.output);
        }
        if (highest == 0 || m_stop) return;
        const Result<DeadTimes> read = m_connection.readDeadTimes(highest);
        if (read) m_deadTimes = *read;
    }

    ItemOutcome<qint32> writeDeadTime(const DeadTimeWrite& write) {
        ValueOps<qint32> ops;
        ops.read = [this, &write]() -> Result<qint32> {
            const Result<DeadTimes> read = m_connection.readDeadTimes(write.output);
            if (!read) return read.error();
            return read->value(write.output, 0);
        };
        ops.write = [this, &write](const qint32&) {
            return m_connection.writeDeadTime(write.output, write.wanted);
        };
        ops.same = [](const qint32& a, const qint32& b) { return a == b; };
        ops.text = deadTimeText;
        std::optional<qint32> before = write.believed;
        if (!before && m_deadTimes) before = m_deadTimes->value(write.output, 0);
        return writeItem<qint32>(deadTimeLabel(write.output), write.wanted, before, ops);
    }

    // One read of every output's mode before the first mode write, instead
    // of one read per item.
    void fillDeadTimeModeBeliefs() {
        int highest = 0;
        for (const DeadTimeModeWrite& write : m_plan.deadTimeModes) {
            if (!write.believed) highest = std::max(highest, write.output);
        }
        if (highest == 0 || m_stop || !m_connection.has(CamConCapability::DeadTimeModes)) return;
        const Result<DeadTimeModes> read = m_connection.readDeadTimeModes(highest);
        if (read) m_deadTimeModes = *read;
    }

    // An item of a section this protocol does not reach: not sent, and
    // said so (empty when the protocol has it).
    template <class T>
    std::optional<ItemOutcome<T>> unreachable(CamConCapability capability, const QString& label) {
        if (m_connection.has(capability)) return std::nullopt;
        ItemOutcome<T> outcome;
        outcome.label = label;
        outcome.error = m_connection.missing(capability);
        m_progress.report(m_done++, m_total, outcome.label);
        return outcome;
    }

    ItemOutcome<OutputDeadTime> writeDeadTimeMode(const DeadTimeModeWrite& write) {
        if (auto no = unreachable<OutputDeadTime>(CamConCapability::DeadTimeModes,
                                                  deadTimeModeLabel(write.output)))
            return *no;
        ValueOps<OutputDeadTime> ops;
        ops.read = [this, &write]() -> Result<OutputDeadTime> {
            const Result<DeadTimeModes> read = m_connection.readDeadTimeModes(write.output);
            if (!read) return read.error();
            return read->value(write.output);
        };
        ops.write = [this, &write](const OutputDeadTime&) {
            return m_connection.writeDeadTimeMode(write.output, write.wanted);
        };
        ops.same = [](const OutputDeadTime& a, const OutputDeadTime& b) { return a == b; };
        ops.text = deadTimeModeText;
        std::optional<OutputDeadTime> before = write.believed;
        if (!before && m_deadTimeModes) before = m_deadTimeModes->value(write.output);
        return writeItem<OutputDeadTime>(deadTimeModeLabel(write.output), write.wanted, before,
                                         ops);
    }

    ItemOutcome<AnalogueCamTrack> writeAnalogueCams(const AnalogueCamWrite& write) {
        const QString label = analogueCamsLabel(write.wanted.output);
        if (auto no = unreachable<AnalogueCamTrack>(CamConCapability::AnalogueCams, label))
            return *no;
        if (auto absent = absentAnalogueOutput(write.wanted, label)) return *absent;
        ValueOps<AnalogueCamTrack> ops;
        ops.read = [this, &write] { return m_connection.readAnalogueCams(write.wanted.output); };
        ops.write = [this, &write](const AnalogueCamTrack&) {
            return m_connection.writeAnalogueCams(write.wanted);
        };
        ops.same = [](const AnalogueCamTrack& a, const AnalogueCamTrack& b) {
            return a.points == b.points;
        };
        ops.text = analogueCamsText;
        return writeItem<AnalogueCamTrack>(label, write.wanted, write.believed, ops);
    }

    // An analogue output beyond the number the device says it has does not
    // exist there (its area is refused): nothing is sent for it. A track
    // without base points is what such an output holds; one with base
    // points is not written and says why. The number is read once, at the
    // first analogue item, after the settings (which may change it).
    std::optional<ItemOutcome<AnalogueCamTrack>> absentAnalogueOutput(
        const AnalogueCamTrack& wanted, const QString& label) {
        if (m_stop) return std::nullopt;
        if (!m_analogueOutputs) {
            const Result<int> count = m_connection.readAnalogueOutputCount();
            if (!count) return std::nullopt;  // the item's own read says what failed
            m_analogueOutputs = *count;
        }
        if (wanted.output <= *m_analogueOutputs) return std::nullopt;
        ItemOutcome<AnalogueCamTrack> outcome;
        outcome.label = label;
        m_progress.report(m_done++, m_total, label);
        const QString absent =
            *m_analogueOutputs == 0
                ? QCoreApplication::translate("cambench::usecases",
                                              "this device has no analogue outputs")
                : QCoreApplication::translate("cambench::usecases",
                                              "this device has analogue outputs 1..%1 only")
                      .arg(*m_analogueOutputs);
        if (wanted.points.isEmpty()) {
            outcome.state = WriteState::Unchanged;
            outcome.actual = wanted;
            outcome.actualText = analogueCamsText(wanted);
            outcome.note = absent;
            return outcome;
        }
        outcome.error = Error::unsupported(
            QCoreApplication::translate("cambench::usecases", "%1; its base points are not written")
                .arg(absent));
        return outcome;  // NotSent
    }

    ItemOutcome<ProgrammingProgram> writeProgrammingProgram(const ProgrammingProgramWrite& write) {
        if (auto no = unreachable<ProgrammingProgram>(CamConCapability::ProgrammingProgram,
                                                      programmingProgramLabel()))
            return *no;
        ValueOps<ProgrammingProgram> ops;
        ops.read = [this] { return m_connection.readProgrammingProgram(); };
        ops.write = [this, &write](const ProgrammingProgram&) {
            return m_connection.writeProgrammingProgram(write.wanted);
        };
        ops.same = [](const ProgrammingProgram& a, const ProgrammingProgram& b) { return a == b; };
        ops.text = programmingProgramText;
        // Reading and writing cams selected their programs; the programming
        // program was set back to what it was before them, so an item the
        // device held already is unchanged (issue 39: it was "written" on
        // every write of an unchanged project). Without that, what the
        // caller believed is no longer the device's state: read it.
        const std::optional<ProgrammingProgram> before =
            m_plan.tracks.isEmpty() ? write.believed : m_programmingAtStart;
        return writeItem<ProgrammingProgram>(programmingProgramLabel(), write.wanted, before, ops);
    }

    ItemOutcome<bool> writeEepromLock(const EepromLockWrite& write) {
        if (auto no = unreachable<bool>(CamConCapability::EepromLock, eepromLockLabel()))
            return *no;
        ValueOps<bool> ops;
        ops.read = [this] { return m_connection.readEepromLock(); };
        ops.write = [this, &write](const bool&) {
            return m_connection.writeEepromLock(write.wanted);
        };
        ops.same = [](const bool& a, const bool& b) { return a == b; };
        ops.text = eepromLockText;
        // Nothing else changes the lock: as read at the start it still is.
        return writeItem<bool>(eepromLockLabel(), write.wanted,
                               m_lockedAtStart ? m_lockedAtStart : write.believed, ops);
    }

    // Reading and writing cams over the table interface selects their
    // program as the programming program, which a PLC may be editing: the
    // write leaves it as it found it, and then writes the plan's item
    // against that.
    std::optional<ProgrammingProgram> programmingBeforeTracks() {
        if (m_plan.tracks.isEmpty() || !m_connection.has(CamConCapability::ProgrammingProgram))
            return std::nullopt;
        const Result<ProgrammingProgram> read = m_connection.readProgrammingProgram();
        return read ? std::optional<ProgrammingProgram>(*read) : std::nullopt;
    }

    // True when the device holds `before` again.
    bool setProgrammingProgramBack(const ProgrammingProgram& before, WriteReport& report) {
        if (m_stop) return false;
        const Result<ProgrammingProgram> now = m_connection.readProgrammingProgram();
        if (now && *now == before) return true;
        const Status restored = m_connection.writeProgrammingProgram(before);
        if (restored) return true;
        if (m_plan.programmingProgram) return false;  // its item is read and written
        report.notes << QCoreApplication::translate(
                            "cambench::usecases",
                            "Writing the cams changed the programming program; setting it back "
                            "to %1 failed (%2): check it on the Programming program page.")
                            .arg(programmingProgramText(before), restored.error().message);
        return false;
    }

    // Where the EEPROM can be locked, whether it is: with the lock on, what
    // is written lives in RAM only, and the report must say so.
    void readEepromLockFirst() {
        m_lockQuestion = m_connection.has(CamConCapability::EepromLock) &&
                         m_plan.itemCount() > (m_plan.eepromLock ? 1 : 0);
        if (!m_lockQuestion) return;
        const Result<bool> locked = m_connection.readEepromLock();
        if (locked)
            m_lockedAtStart = *locked;
        else
            m_lockError = locked.error().message;
    }

    // The note on the EEPROM lock, empty when there is nothing to say.
    QString eepromNote(const WriteReport& report) const {
        if (!m_lockQuestion) return {};
        int written = 0;
        for (const OutcomeLine& line : report.lines())
            written += line.state == WriteState::Written ? 1 : 0;
        if (report.eepromLock && report.eepromLock->state == WriteState::Written) --written;
        if (written == 0) return {};
        // After an unlock first the lock state is the unlock's outcome.
        const bool lockedWhileWriting =
            report.eepromLockFirst
                ? !(report.eepromLock && report.eepromLock->actual == std::optional<bool>(false))
                : m_lockedAtStart.value_or(false);
        if (!m_lockError.isEmpty() && !report.eepromLockFirst) {
            return QCoreApplication::translate(
                       "cambench::usecases",
                       "Whether the device's EEPROM is locked could not be read (%1): if it is, "
                       "what was written is held in RAM only and is lost when the device is "
                       "switched off.")
                .arg(m_lockError);
        }
        if (!lockedWhileWriting) return {};
        return QCoreApplication::translate(
            "cambench::usecases",
            "The device's EEPROM is locked: what was written is held in RAM only and is lost "
            "when the device is switched off. Unlock the EEPROM to keep it.");
    }

    ItemOutcome<std::optional<User>> writeUser(const UserWrite& write) {
        using MaybeUser = std::optional<User>;
        const User* current = findUser(m_users, write.deviceNumber);
        const MaybeUser before = current ? MaybeUser(*current) : MaybeUser();
        // Where to look for the user after the write: its new number, else the old one.
        const QString number = write.wanted ? write.wanted->number : write.deviceNumber;
        ValueOps<MaybeUser> ops;
        ops.read = [this, number, &write]() -> Result<MaybeUser> {
            const Result<QList<User>> users = m_connection.readUsers();
            if (!users) return users.error();
            m_users = *users;
            if (const User* user = findUser(m_users, number)) return MaybeUser(*user);
            if (const User* user = findUser(m_users, write.deviceNumber)) return MaybeUser(*user);
            return MaybeUser();
        };
        ops.write = [this, &write](const MaybeUser&) -> Status {
            const Status done = write.wanted
                                    ? m_connection.writeUser(write.deviceNumber, *write.wanted)
                                    : m_connection.deleteUser(write.deviceNumber);
            if (done) applyToUsers(write);
            return done;
        };
        ops.same = sameUser;
        ops.text = userText;
        const QString name = write.wanted ? write.wanted->name : before ? before->name : QString();
        return writeItem<MaybeUser>(userLabel(name), write.wanted, before, ops);
    }

    void applyToUsers(const UserWrite& write) {
        for (int i = 0; i < m_users.size(); ++i) {
            if (m_users.at(i).number != write.deviceNumber || write.deviceNumber.isEmpty())
                continue;
            if (write.wanted)
                m_users[i] = *write.wanted;
            else
                m_users.removeAt(i);
            return;
        }
        if (write.wanted) m_users.append(*write.wanted);
    }

    ItemOutcome<PlcNetwork> writePlcNetwork(const PlcWrite& write) {
        ValueOps<PlcNetwork> ops;
        ops.read = [this, &write] {
            return m_connection.readPlcNetwork(write.wanted.area, write.wanted.number);
        };
        ops.write = [this, &write](const PlcNetwork&) {
            return m_connection.writePlcNetwork(write.wanted);
        };
        ops.same = [](const PlcNetwork& a, const PlcNetwork& b) { return a == b; };
        ops.text = plcText;
        return writeItem<PlcNetwork>(plcLabel(write.wanted), write.wanted, write.believed, ops);
    }

    CamConDevice& m_connection;
    const WritePlan& m_plan;
    const LinkSettings& m_link;
    const UseCaseProgress& m_progress;
    SystemSettings m_settings;  // the device's settings as known now
    QList<User> m_users;        // the device's users as known now
    std::optional<DeadTimes> m_deadTimes;
    std::optional<DeadTimeModes> m_deadTimeModes;
    std::optional<int> m_analogueOutputs;  // as the device says, read at the first analogue item
    bool m_lockQuestion = false;           // the protocol has the lock and items are written
    std::optional<bool> m_lockedAtStart;   // the EEPROM lock before the first item
    // The programming program before the cams were read and written, once
    // it has been set back to it.
    std::optional<ProgrammingProgram> m_programmingAtStart;
    QString m_lockError;          // why the lock could not be read
    std::optional<Error> m_stop;  // set: the remaining items are not sent
    qint64 m_done = 0;
    qint64 m_total = 0;
};

bool needsSettings(const WritePlan& plan) {
    return !plan.settings.isEmpty() || !plan.tracks.isEmpty() || !plan.plcNetworks.isEmpty();
}

// The settings as they will be when the plan's settings are written
// first: they decide the axis type and the PLC counts the rest is checked
// against.
SystemSettings settingsAfter(const WritePlan& plan) {
    SystemSettings settings = plan.settingsOnDevice.value_or(SystemSettings());
    for (const SettingsWrite& group : plan.settings) {
        for (auto it = group.wanted.cbegin(); it != group.wanted.cend(); ++it)
            settings.insert(it.key(), *it);
    }
    return settings;
}

}  // namespace

Result<WriteReport> writeItems(CamConDevice& connection, const DeviceInfo& device,
                               const WritePlan& plan, const UseCaseProgress& progress) {
    WritePlan resolved = plan;
    if (!resolved.settingsOnDevice && needsSettings(plan)) {
        progress.report(0, plan.itemCount(),
                        QCoreApplication::translate("cambench::usecases", "reading the settings"));
        Result<SystemSettings> settings = connection.readSettings();
        if (!settings) return settings.error();
        resolved.settingsOnDevice = *settings;
    }
    if (!resolved.usersOnDevice && !plan.users.isEmpty()) {
        progress.report(0, plan.itemCount(),
                        QCoreApplication::translate("cambench::usecases", "reading the users"));
        Result<QList<User>> users = connection.readUsers();
        if (!users) return users.error();
        resolved.usersOnDevice = *users;
    }
    if (resolved.usersOnDevice) resolveUserNumbers(resolved);
    const LinkSettings link = takeLinkSettings(resolved);

    // Checked with the communication settings that will be written.
    WritePlan checked = resolved;
    checked.settings += link.asked;
    CheckContext context;
    const SystemSettings after = settingsAfter(checked);
    context.rotary = isRotaryAxis(after);
    context.plcNetworksPerArea = plcNetworkCounts(after);
    context.usersOnDevice = resolved.usersOnDevice.value_or(QList<User>());
    const PlanCheck check = checkPlan(checked, device, context);
    if (!check.fits()) return check.refusal(device);
    if (progress.cancelled()) return Error::cancelled();
    return Writer(connection, resolved, link, progress).run();
}

}  // namespace cambench::usecases
