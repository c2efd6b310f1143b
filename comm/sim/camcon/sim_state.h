#pragma once

#include "sim_cam_store.h"

#include "comm/camcon/ascii/fields.h"

#include <QByteArray>
#include <QList>
#include <QMap>

#include <array>
#include <utility>

namespace cambench::comm {

// A key-assignment entry as the device stores it (notes 4).
struct SimUser {
    static constexpr int kAccessBytes = 32;
    QByteArray name;                                     // without NUL padding
    QByteArray number;                                   // the access code, a secret
    QByteArray access = QByteArray(kAccessBytes, '\0');  // bit per output
    bool allOutputs = false;
    quint32 rights = 0;
    friend bool operator==(const SimUser& a, const SimUser& b) {
        return a.name == b.name && a.number == b.number && a.access == b.access &&
               a.allOutputs == b.allOutputs && a.rights == b.rights;
    }
};

// One network of the PLC logic matrix (notes 5), raw words.
struct SimPlcNetwork {
    static constexpr int kSymbols = 30;
    qint32 value = 0;
    quint16 reset = 0;
    std::array<quint16, kSymbols> symbols{};
    bool isEmpty() const;
    friend bool operator==(const SimPlcNetwork& a, const SimPlcNetwork& b) {
        return a.value == b.value && a.reset == b.reset && a.symbols == b.symbols;
    }
};

// Settings are kept as the decoded fields of their command, under the
// command name and an index (-1 for single values, the channel for ?AMODE).
using SimSettingKey = std::pair<QByteArray, int>;
using SimPlcKey = std::pair<int, int>;  // area (0x08..0x0B), 0-based number

// Everything a CamCon keeps in its EEPROM: what a backup carries and a
// restore brings back. Runtime values (axis, cursor, timers) live elsewhere.
struct SimState {
    static constexpr int kPlcTextLines = 4;

    SimCamStore cams;
    QMap<int, qint32> deadTimes;         // output (0-based) -> 0.1 ms
    QMap<int, QByteArray> outputNames;   // output (0-based)
    QMap<int, QByteArray> programNames;  // program
    QList<SimUser> users;                // in the order ?USER lists them
    QMap<SimPlcKey, SimPlcNetwork> plcNetworks;
    QMap<SimSettingKey, Fields> settings;
    QMap<int, QByteArray> userTexts;                            // ?BTXT line -> text
    QMap<int, std::array<QByteArray, kPlcTextLines>> plcTexts;  // ?ETXT message -> lines
    int activeProgram = 0;

    friend bool operator==(const SimState& a, const SimState& b) {
        return a.cams == b.cams && a.deadTimes == b.deadTimes && a.outputNames == b.outputNames &&
               a.programNames == b.programNames && a.users == b.users &&
               a.plcNetworks == b.plcNetworks && a.settings == b.settings &&
               a.userTexts == b.userTexts && a.plcTexts == b.plcTexts &&
               a.activeProgram == b.activeProgram;
    }
};

}  // namespace cambench::comm
