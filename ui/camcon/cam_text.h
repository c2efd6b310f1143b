#pragma once

#include "model/camcon/cam_program.h"

#include <QCoreApplication>
#include <QStringList>

namespace cambench {

// A track's cams as the GUI shows them in lists and reports: "10–90,
// 180–270", or "no cams".
inline QString camsText(const Track& track) {
    if (track.cams.isEmpty()) return QCoreApplication::translate("cambench::CamText", "no cams");
    QStringList cams;
    for (const Cam& cam : track.cams) cams << QStringLiteral("%1–%2").arg(cam.on).arg(cam.off);
    return cams.join(QStringLiteral(", "));
}

}  // namespace cambench
