#pragma once

#include "model/camcon/cam_program.h"
#include "model/camcon/device_info.h"
#include "ui/camcon/cameditor/cam_document.h"

namespace cambench::test {

// A rotary device 0..359 with 8 outputs and 4 programs.
inline DeviceInfo smallDevice() {
    DeviceInfo info;
    info.outputs = 8;
    info.deadTimeOutputs = 8;
    info.programs = 4;
    info.minPosition = 0;
    info.maxPosition = 359;
    return info;
}

// Program 0 as read from the device: output 1 has two cams, output 3 one
// that wraps through zero.
inline CamProgram demoProgram() {
    CamProgram program;
    program.number = 0;
    program.name = QStringLiteral("Demo");
    program.tracks.insert(1, Track{1, {{20, 60}, {100, 150}}});
    program.tracks.insert(3, Track{3, {{330, 30}}});
    return program;
}

inline void loadDemo(CamDocument& document) {
    document.setLimits(smallDevice(), true);
    document.loadProgramFromDevice(demoProgram());
}

}  // namespace cambench::test
