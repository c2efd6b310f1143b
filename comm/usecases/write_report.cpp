#include "write_report.h"

namespace cambench::usecases {

QString writeStateText(WriteState) {
    return {};
}

int WriteReport::count(WriteState) const {
    return 0;
}
int WriteReport::total() const {
    return 0;
}
bool WriteReport::complete() const {
    return false;
}
Error WriteReport::firstError() const {
    return {};
}
QList<OutcomeLine> WriteReport::lines() const {
    return {};
}
QString WriteReport::summary() const {
    return {};
}

}  // namespace cambench::usecases
