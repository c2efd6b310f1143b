#include "mc1_points_page.h"

#include "ui/device_session.h"
#include "ui/led_strip.h"
#include "ui/live_freshness.h"
#include "ui/sentence.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QScrollArea>
#include <QSpinBox>
#include <QVBoxLayout>

namespace cambench {

using comm::Mc1Area;
using comm::Mc1Point;

Mc1PointsPage::Mc1PointsPage(DeviceSession* session, QWidget* parent)
    : Mc1Page(session, parent), m_flagFirst(new QSpinBox), m_flagCount(new QSpinBox) {
    setObjectName(QStringLiteral("mc1PointsPage"));
    auto* content = new QWidget;
    auto* column = new QVBoxLayout(content);
    const std::pair<Mc1Area, QString> areas[] = {
        {Mc1Area::Input, tr("Inputs (E)")},
        {Mc1Area::Output, tr("Outputs (A) - click to set or clear")},
        {Mc1Area::Flag, tr("Flags (M) - click to set or clear")}};
    for (const auto& [area, title] : areas) {
        auto* box = new QGroupBox(title);
        auto* strip = new LedStrip;
        strip->setObjectName(area == Mc1Area::Input    ? QStringLiteral("mc1Inputs")
                             : area == Mc1Area::Output ? QStringLiteral("mc1Outputs")
                                                       : QStringLiteral("mc1Flags"));
        auto* inner = new QVBoxLayout(box);
        if (area == Mc1Area::Flag) {
            auto* range = new QHBoxLayout;
            m_flagFirst->setRange(1, 3584);
            m_flagFirst->setPrefix(QStringLiteral("M"));
            m_flagFirst->setObjectName(QStringLiteral("mc1FlagFirst"));
            m_flagCount->setRange(8, 256);
            m_flagCount->setSingleStep(8);
            m_flagCount->setValue(64);
            range->addWidget(new QLabel(tr("From")));
            range->addWidget(m_flagFirst);
            range->addWidget(new QLabel(tr("count")));
            range->addWidget(m_flagCount);
            range->addStretch();
            inner->addLayout(range);
            connect(m_flagFirst, &QSpinBox::valueChanged, this, [this] { layoutFlags(); });
            connect(m_flagCount, &QSpinBox::valueChanged, this, [this] { layoutFlags(); });
        }
        inner->addWidget(strip);
        column->addWidget(box);
        m_areas << Area{area, strip, {}};
        if (area != Mc1Area::Input) {
            connect(strip, &LedStrip::ledClicked, this, [this, area = area](int index) {
                for (const Area& a : m_areas) {
                    if (a.area != area || index >= a.numbers.size()) continue;
                    toggle(Mc1Point{area, a.numbers.at(index)}, !a.strip->states().value(index));
                }
            });
        }
    }
    column->addStretch();
    auto* scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setWidget(content);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(scroll, 1);
    layout->addWidget(freshnessLine());
    layout->addWidget(resultLine());
}

LedStrip* Mc1PointsPage::strip(Mc1Area area) const {
    for (const Area& a : m_areas)
        if (a.area == area) return a.strip;
    return nullptr;
}

void Mc1PointsPage::factsChanged() {
    const bool mc200 = comm::isMc200(facts().variant);
    for (Area& a : m_areas) {
        if (a.area == Mc1Area::Flag) continue;
        a.numbers = facts().known ? comm::mc1PointNumbers(a.area, mc200) : QList<int>();
        a.strip->setNumbers(a.numbers);
        a.strip->setCount(int(a.numbers.size()));
    }
    layoutFlags();
}

void Mc1PointsPage::layoutFlags() {
    const bool mc200 = comm::isMc200(facts().variant);
    const QList<int> all =
        facts().known ? comm::mc1PointNumbers(Mc1Area::Flag, mc200) : QList<int>();
    QList<int> shown;
    for (int n : all)
        if (n >= m_flagFirst->value() && shown.size() < m_flagCount->value()) shown << n;
    for (Area& a : m_areas) {
        if (a.area != Mc1Area::Flag) continue;
        a.numbers = shown;
        a.strip->setNumbers(shown);
        a.strip->setStates(QList<bool>(shown.size(), false));
        a.strip->setStale(true);
    }
    poll();
}

bool Mc1PointsPage::poll() {
    if (!facts().known) return true;
    QList<Mc1Point> points;
    for (const Area& a : m_areas)
        for (int n : a.numbers) points << Mc1Point{a.area, n};
    if (points.isEmpty()) return true;
    runPoll<comm::Mc1Device, QList<bool>>(
        tr("Read flags and I/O"),
        [points](comm::Mc1Device& device, comm::JobContext& job) {
            // Answers arriving: many points are slow to read, not silent.
            return device.readPoints(
                points, [&job](qint64 done, qint64 total) { job.progress(done, total); });
        },
        [this, points](const QList<bool>& values) {
            int at = 0;
            for (Area& a : m_areas) {
                // The flag range may have changed meanwhile: only a match is shown.
                const QList<bool> part = values.mid(at, a.numbers.size());
                bool same = at + a.numbers.size() <= points.size();
                for (int i = 0; same && i < a.numbers.size(); ++i)
                    same = points.at(at + i).area == a.area &&
                           points.at(at + i).number == a.numbers.at(i);
                at += int(a.numbers.size());
                if (!same) continue;
                a.strip->setStates(part);
                a.strip->setStale(false);
            }
        },
        QStringLiteral("mc1-points"));
    return true;
}

void Mc1PointsPage::markStale() {
    for (const Area& a : m_areas) {
        a.strip->setStale(true);
        a.strip->setToolTip(freshness()->describe());
    }
}

void Mc1PointsPage::freshnessChanged() {
    if (!freshness()->isLive()) {
        markStale();
        return;
    }
    for (const Area& a : m_areas) a.strip->setToolTip({});
}

void Mc1PointsPage::toggle(const Mc1Point& point, bool on) {
    const QString name = comm::mc1PointText(point);
    const QString controller = comm::mc1VariantName(facts().variant);
    const QString question = on ? tr("Set %1 on the %2?").arg(name, controller)
                                : tr("Clear %1 on the %2?").arg(name, controller);
    const QString detail =
        point.area == Mc1Area::Output
            ? tr("The output switches at once; whatever it drives on the machine acts.")
            : tr("The PLC program sees the flag at once.");
    if (!confirm(on ? tr("Set") : tr("Clear"), question, detail)) return;
    session()->run<comm::Mc1Device, bool>(
        this, tr("Write flag or output"),
        [point, on](comm::Mc1Device& device, comm::JobContext&) {
            return device.writePoint(point, on);
        },
        [this, point, on, name](Result<bool> back) {
            if (!back) {
                showResult(asSentence(back.error().message), false);
                markStale();
                return;
            }
            for (Area& a : m_areas) {
                if (a.area != point.area) continue;
                const int index = int(a.numbers.indexOf(point.number));
                if (index < 0) continue;
                QList<bool> states = a.strip->states();
                states[index] = *back;
                a.strip->setStates(states);
            }
            showResult(*back == on
                           ? tr("%1 = %2, read back.").arg(name).arg(*back ? 1 : 0)
                           : tr("%1 reads back %2 after the write.").arg(name).arg(*back ? 1 : 0),
                       *back == on);
        });
}

}  // namespace cambench
