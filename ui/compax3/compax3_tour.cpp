// The screenshot tour's stops on a Compax3 (`cambench --screenshots DIR`):
// every page on a drive on RS232, and the RS485 line with its bus scan.

#include "compax3_window.h"

#include "compax3_motion_page.h"
#include "compax3_object_model.h"
#include "compax3_objects_page.h"
#include "compax3_parameters_page.h"
#include "compax3_status_page.h"
#include "compax3_watch_page.h"

#include "model/compax3/compax3_parameter_file.h"
#include "ui/main_window.h"
#include "ui/multi_trend_chart.h"
#include "ui/screenshot_tour.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QTableWidget>

#include <memory>

namespace cambench {

namespace {
const QString kRs485 = QStringLiteral("compax3-rs485");
constexpr int kWatchSamples = 4;  // enough of a line to see it move

// The saved parameters as if from the drive before it broke: one numeric
// value changed, so that the comparison has a difference to show.
bool changeOneValue(const QString& path) {
    const Result<Compax3ParameterSet> saved = loadCompax3Parameters(path);
    if (!saved) return false;
    Compax3ParameterSet set = *saved;
    for (Compax3ParameterValue& value : set.values) {
        bool number = false;
        const double was = value.value.toDouble(&number);
        if (!number) continue;
        value.value = QString::number(was + 1);
        return saveCompax3Parameters(path, set).ok();
    }
    return false;
}
}  // namespace

QList<TourVisit> Compax3Window::tourVisits() const {
    return {
        {QStringLiteral("compax3"), QStringLiteral("sim"), QStringLiteral("compax3")},
        {kRs485, QStringLiteral("sim:address=7"), kRs485, 7},
    };
}

QList<TourStop> Compax3Window::tourStops(const TourVisit& visit, const QString& directory) {
    if (visit.protocol == kRs485) {
        return {
            scannedConnectionStop(window()),
            {QStringLiteral("02-status"),
             [this] { window()->showPage(m_status); },
             [this] { return facts().known && !m_status->errorText().isEmpty(); },
             {}},
        };
    }
    const QString parameters =
        QDir(directory).filePath(QStringLiteral("screenshot-compax3-parameters.json"));
    auto compared = std::make_shared<bool>(false);
    auto* result = m_parameters->findChild<QLabel*>(QStringLiteral("pageResult"));
    return {
        {QStringLiteral("01-objects"),
         [this] { window()->showPage(m_objects); },
         [this] {
             return facts().known &&
                    m_objects->model()->driveValue(comm::kCompax3Position).has_value();
         },
         {}},
        {QStringLiteral("02-status"),
         [this] { window()->showPage(m_status); },
         [this] { return facts().known && !m_status->errorText().isEmpty(); },
         {}},
        {QStringLiteral("03-motion"),
         [this] { window()->showPage(m_motion); },
         [this] { return facts().known; },
         {}},
        {QStringLiteral("04-watch"),
         [this] { window()->showPage(m_watch); },
         [this] {
             const int series = std::max(1, m_watch->chart()->seriesCount());
             return m_watch->chart()->pointCount() >= kWatchSamples * series;
         },
         {}},
        {QStringLiteral("05-parameters"),
         [this, parameters] {
             window()->showPage(m_parameters);
             QFile::remove(parameters);
             m_parameters->saveToFile(parameters);
         },
         [this, parameters, compared, result] {
             // Saved, then compared with one value changed in the file.
             if (!*compared) {
                 if (!QFileInfo::exists(parameters) || !changeOneValue(parameters)) return false;
                 *compared = true;
                 m_parameters->compareWith(parameters);
                 return false;
             }
             return m_parameters->differences()->rowCount() > 0 && result &&
                    !result->text().isEmpty();
         },
         {}},
    };
}

}  // namespace cambench
