#pragma once

#include <QList>
#include <QString>

#include <optional>

namespace cambench::comm {

// The four MC-1 dialects (docs/protocols/mc1.md, "Variants"). They differ in
// which telegrams exist and in what some opcodes mean: D5 is RDBLOCK on an
// MC100 V2 but RDMEM6 on an MC200; RDVAR answers 24 bits on an MC100 and
// 32 bits on an MC200.
enum class Mc1Variant {
    Mc100V1,  // MC100, single FIFO cards (MC100MA: 0xFF synchronisation)
    Mc100V2,  // MC100MA, OS >= 5.26, dual FIFO: + RDBLOCK
    Mc200V1,  // MC200, CPU OS <= 1.30: 32-bit variables, status and table telegrams
    Mc200V2,  // MC200: + memory, SYSDATA and axis telegrams
};

QList<Mc1Variant> allMc1Variants();
// "mc100v1" ... "mc200v2": the command line's and the files' names.
QString mc1VariantKey(Mc1Variant variant);
std::optional<Mc1Variant> mc1VariantFromKey(const QString& key);
// "MC200 V2": what a person reads.
QString mc1VariantName(Mc1Variant variant);
bool isMc200(Mc1Variant variant);
// Variables: 24 bits on an MC100, 32 on an MC200 (both signed).
int mc1VariableBits(Mc1Variant variant);

}  // namespace cambench::comm
