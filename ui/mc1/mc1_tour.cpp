// The screenshot tour's stops on an MC100/MC200 (`cambench --screenshots
// DIR`): every page on an MC200 with its binary protocol, and what an
// MC100 speaking ASCII shows (variables, flags and I/O; no program, axes
// or memory).

#include "mc1_window.h"

#include "mc1_axes_page.h"
#include "mc1_gui.h"
#include "mc1_memory_page.h"
#include "mc1_points_page.h"
#include "mc1_program_page.h"
#include "mc1_trend_page.h"
#include "mc1_variables_page.h"
#include "mc1_watch_model.h"

#include "ui/main_window.h"

#include <QLabel>
#include <QPlainTextEdit>

namespace cambench {

namespace {
const QString kAscii = QStringLiteral("mc1-ascii");
constexpr int kTrendSamples = 4;  // enough of a line to see it move
}  // namespace

QList<TourVisit> Mc1Window::tourVisits() const {
    return {
        {QStringLiteral("mc1"), QStringLiteral("sim:variant=mc200v2"), QStringLiteral("mc1")},
        {kAscii, QStringLiteral("sim:variant=mc100v2"), kAscii},
    };
}

QList<TourStop> Mc1Window::tourStops(const TourVisit& visit, const QString& directory) {
    Q_UNUSED(directory);
    const auto watched = [this] {
        return facts().known && m_mc1->watchList()->entries().value(0).value.has_value();
    };
    const TourStop variables{
        QStringLiteral("01-variables"), [this] { window()->showPage(m_variables); }, watched, {}};
    const TourStop points{QStringLiteral("02-flags-io"),
                          [this] { window()->showPage(m_points); },
                          [this] { return facts().known; },
                          {}};
    if (visit.protocol == kAscii) return {variables, points};
    return {
        variables,
        points,
        {QStringLiteral("03-program"),
         [this] { window()->showPage(m_program); },
         [this] {
             const QString status = m_program->statusLabel()->text();
             return facts().known && !status.isEmpty() && status != QStringLiteral("—");
         },
         {}},
        {QStringLiteral("04-axes"),
         [this] { window()->showPage(m_axes); },
         [this] { return facts().known && !m_axes->stateLabel()->text().isEmpty(); },
         {}},
        {QStringLiteral("05-memory"),
         [this] {
             window()->showPage(m_memory);
             m_memory->read(0, 256);
         },
         [this] { return !m_memory->hexView()->toPlainText().isEmpty(); },
         {}},
        {QStringLiteral("06-trend"),
         [this] { window()->showPage(m_trend); },
         [this] {
             return m_trend->pointCount() >= kTrendSamples * std::max(1, m_trend->seriesCount());
         },
         {}},
    };
}

}  // namespace cambench
