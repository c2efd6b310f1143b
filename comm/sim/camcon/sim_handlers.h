#pragma once

#include "sim_profile.h"
#include "sim_state.h"

namespace cambench::comm {

class SimDevice;

// Command handlers by manual section; each adds its commands to the device.
void registerStatusHandlers(SimDevice& device);  // 5.1 display menu, axis, ?PAU
void registerCamHandlers(SimDevice& device);     // 5.2 programming, dead times
void registerNameHandlers(SimDevice& device);    // output/program names, ?BTXT, ?ETXT
void registerUserHandlers(SimDevice& device);    // 5.4.1 key assignment
void registerPlcHandlers(SimDevice& device);     // 5.5 PLC matrix, timers
void registerEepromHandlers(SimDevice& device);  // 5.6 ?EE / !EE
void registerInfoHandlers(SimDevice& device);    // 5.4.2, 5.4.7, 5.7, checksums, ?UNIT
// Special-encoder pages, ?AMODE and every remaining single-value setting of
// the catalogue. Registered last: it takes the commands nobody else took.
void registerSettingsHandlers(SimDevice& device);

// The state of a freshly cleared device: default settings, no cams.
SimState defaultState(const SimProfile& profile, int deviceNumber);

}  // namespace cambench::comm
