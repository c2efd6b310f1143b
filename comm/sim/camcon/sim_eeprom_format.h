#pragma once

#include "sim_profile.h"
#include "sim_state.h"

#include "model/result.h"

#include <QByteArray>
#include <QList>

namespace cambench::comm::sim_eeprom {

// The simulator's own EEPROM layout (the real one is opaque, notes 6).
// Block 0000 holds 128 bytes of basic parameters; every later block is one
// record whose first byte carries the block length in its upper nibble
// (n * 6 bytes, counting that byte) and the record type in its lower one.
constexpr int kBasicBlockBytes = 128;
constexpr int kMaxBlockBytes = 15 * 6;

// Length a block must have for its first byte; 0 for a nibble of 0.
int blockLength(quint8 firstByte);

// The state as blocks, block 0000 first. Deterministic: equal states give
// equal blocks.
QList<QByteArray> serialize(const SimState& state, const SimProfile& profile);

// Inverse of serialize(). Fails when a block is not one of ours or does not
// fit the device (program, output or cam out of range).
Result<SimState> parse(const QList<QByteArray>& blocks, const SimProfile& profile);

}  // namespace cambench::comm::sim_eeprom
