#include "mc1_settings.h"

#include <QSettings>

namespace cambench::mc1settings {

namespace {
const QString kWatchListKey = QStringLiteral("mc1/watchList");
}  // namespace

void saveWatchList(const Mc1Project& project) {
    Mc1Project names = project;
    for (Mc1NamedValue& variable : names.variables) variable.value.reset();
    for (Mc1NamedValue& flag : names.flags) flag.value.reset();
    QSettings().setValue(kWatchListKey, mc1ProjectToJson(names));
}

std::optional<Mc1Project> loadWatchList() {
    const QByteArray kept = QSettings().value(kWatchListKey).toByteArray();
    if (kept.isEmpty()) return std::nullopt;
    Result<Mc1Project> project = mc1ProjectFromJson(kept);
    if (!project) return std::nullopt;
    return *project;
}

}  // namespace cambench::mc1settings
