#pragma once

#include <QString>
#include <QStringList>

namespace cambench::comm {

// One connection setting a protocol takes beside the line's (port, baud):
// the device number on a bus, the PC's own number there, a drive's address,
// the controller variant to expect. A protocol declares each of its options
// once, in its ProtocolInfo; the command line (--name), a machine file
// ("name": value) and the connection page (a field) are all read through
// that declaration (protocol_options.h), so a new option touches only the
// protocol that has it.
struct ProtocolOption {
    // "device": the command line's --device, a machine file's "device".
    QString name;
    // Other names it is given by: a Compax3 on RS485 is reached by its
    // "address", and machine files have called that "device".
    QStringList aliases;
    // Its key in ProtocolSettings::toMap() / fromMap(): "device", "pcNumber".
    QString settingsKey;
    // Its field on the connection page, "Device number:", and the field's
    // tooltip and the --help line, in English (ui/ and the CLI translate
    // through the "cambench::comm" context).
    QString label;
    QString help;
    // A whole number in [min, max], `fallback` when not given...
    int min = 0;
    int max = 0;
    int fallback = 0;
    // ...or one of these words (lower case; the first is the default).
    QStringList choices;
    // Said always when a connection is written down (a machine file), not
    // only when it differs from the fallback: the device number of a bus.
    bool alwaysWritten = false;

    bool isChoice() const { return !choices.isEmpty(); }
    bool isCalled(const QString& word) const { return word == name || aliases.contains(word); }

    static ProtocolOption number(QString name, QString settingsKey, int min, int max, int fallback,
                                 QString label, QString help) {
        ProtocolOption option;
        option.name = std::move(name);
        option.settingsKey = std::move(settingsKey);
        option.min = min;
        option.max = max;
        option.fallback = fallback;
        option.label = std::move(label);
        option.help = std::move(help);
        return option;
    }
    static ProtocolOption choice(QString name, QString settingsKey, QStringList choices,
                                 QString label, QString help) {
        ProtocolOption option;
        option.name = std::move(name);
        option.settingsKey = std::move(settingsKey);
        option.choices = std::move(choices);
        option.label = std::move(label);
        option.help = std::move(help);
        return option;
    }
};

}  // namespace cambench::comm
