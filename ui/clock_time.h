#pragma once

#include <QString>
#include <QTime>

namespace cambench {

// A time of day on screen, in every language the same: "02:14:07" (24 hours
// and seconds: two STOPs, or a STOP and the last answer, are told apart by
// the second). QLocale's long format said "7:29:03 AM UTC" in English
// beside "07:29:03" on the next line.
inline QString clockTime(const QTime& time) {
    return time.toString(QStringLiteral("HH:mm:ss"));
}

}  // namespace cambench
