#pragma once

#include <QString>

#include <array>

namespace cambench {

// One network (rung) of the PLC logic matrix (manual 5.5, notes 5): an output
// of area O, P, M or X, a value (timer/counter preset), a reset field and
// 5 current paths x 6 symbols.
struct PlcNetwork {
    enum Area { O = 0x08, P = 0x09, M = 0x0A, X = 0x0B };
    static constexpr int kPaths = 5;
    static constexpr int kSymbolsPerPath = 6;
    static constexpr int kSymbols = kPaths * kSymbolsPerPath;

    int area = O;
    int number = 0;  // 0-based, as the ASCII protocol numbers it
    qint32 value = 0;
    quint16 reset = 0;
    std::array<quint16, kSymbols> symbols{};  // path by path

    bool isEmpty() const;
    // "PLC network M3", for messages.
    static QString describe(int area, int number);
    friend bool operator==(const PlcNetwork& a, const PlcNetwork& b) {
        return a.area == b.area && a.number == b.number && a.value == b.value &&
               a.reset == b.reset && a.symbols == b.symbols;
    }
};

// One number for a network's place (area, number): the key the workspace
// keeps networks under.
inline int plcNetworkKey(int area, int number) {
    return (area << 8) | number;
}

}  // namespace cambench
