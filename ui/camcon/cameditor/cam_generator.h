#pragma once

#include "model/camcon/cam_program.h"
#include "model/camcon/cam_validation.h"
#include "model/result.h"

#include <QCoreApplication>
#include <QList>

namespace cambench {

// The multi-cam generator: evenly spaced cams from a start position, either
// by fixed length and pitch or by count and duty cycle.
struct CamGeneratorSettings {
    enum class Mode { LengthAndPitch, CountAndDuty };
    Mode mode = Mode::LengthAndPitch;
    qint32 start = 0;
    qint32 length = 10;
    qint32 pitch = 20;
    int count = 4;
    double dutyPercent = 50.0;
};

class CamGenerator {
    Q_DECLARE_TR_FUNCTIONS(CamGenerator)

public:
    static Result<QList<Cam>> generate(const CamGeneratorSettings& settings, qint32 minPosition,
                                       qint32 maxPosition, bool rotary);
};

}  // namespace cambench
