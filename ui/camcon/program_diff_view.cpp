#include "program_diff_view.h"

#include "ui/camcon/cameditor/diagram_layout.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QMouseEvent>
#include <QPainter>
#include <QPixmap>
#include <QScrollArea>
#include <QSet>
#include <QSplitter>

namespace cambench {

namespace {

constexpr int kRowHeight = 30;
constexpr int kAxisHeight = 24;
constexpr int kLabelWidth = 150;
constexpr int kMargin = 6;

// Colours that read on light and dark palettes; shapes carry the meaning too.
const QColor kOnlyInA(0xc0, 0x39, 0x2b);
const QColor kOnlyInB(0x1e, 0x84, 0x49);
const QColor kMovedEdge(0xe6, 0x7e, 0x22);

// One row of the layout for output `row` (1-based row, not output number).
DiagramLayout layoutFor(const Axis& axis, const QRect& plot) {
    DiagramLayout layout;
    layout.setAxis(axis);
    layout.setPlotArea(plot, kRowHeight, 0);
    layout.fit();
    return layout;
}

// A legend entry: the swatch as the diagram draws it, and its meaning.
QWidget* legendEntry(ProgramDiffView::Swatch swatch, const QString& text, const QPalette& palette) {
    QPixmap pixmap(36, 16);
    pixmap.fill(palette.color(QPalette::Base));
    QPainter painter(&pixmap);
    ProgramDiffView::paintSwatch(painter, QRectF(1, 1, 34, 14), swatch, palette);
    painter.end();
    auto* entry = new QWidget;
    auto* layout = new QHBoxLayout(entry);
    layout->setContentsMargins(0, 0, 8, 0);
    auto* icon = new QLabel;
    icon->setPixmap(pixmap);
    layout->addWidget(icon);
    layout->addWidget(new QLabel(text));
    return entry;
}

// The legend's words kept where they were first translated.
QString legendText(const char* text) {
    return QCoreApplication::translate("cambench::CompareProgramsDialog", text);
}

}  // namespace

QSplitter* ProgramDiffView::besideList(ProgramDiffView* view, QListWidget* list, QCheckBox* fold) {
    auto* scroll = new QScrollArea;
    scroll->setWidget(view);
    scroll->setWidgetResizable(true);
    list->setObjectName(QStringLiteral("differenceList"));
    auto* splitter = new QSplitter;
    splitter->addWidget(scroll);
    splitter->addWidget(list);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 1);
    connect(fold, &QCheckBox::toggled, view, &ProgramDiffView::setFoldUnchanged);
    connect(list, &QListWidget::currentRowChanged, view, &ProgramDiffView::setSelected);
    connect(view, &ProgramDiffView::differenceClicked, list,
            [list](int row) { list->setCurrentRow(row); });
    return splitter;
}

QLayout* ProgramDiffView::legend(const QPalette& palette) {
    auto* legend = new QHBoxLayout;
    legend->addWidget(legendEntry(
        Swatch::Same,
        legendText(QT_TRANSLATE_NOOP("cambench::CompareProgramsDialog", "the same in both")),
        palette));
    legend->addWidget(
        legendEntry(Swatch::Changed,
                    legendText(QT_TRANSLATE_NOOP("cambench::CompareProgramsDialog",
                                                 "changed: A dashed, B solid, moved edges marked")),
                    palette));
    legend->addWidget(legendEntry(
        Swatch::OnlyInA,
        legendText(QT_TRANSLATE_NOOP("cambench::CompareProgramsDialog", "only in A")), palette));
    legend->addWidget(legendEntry(
        Swatch::OnlyInB,
        legendText(QT_TRANSLATE_NOOP("cambench::CompareProgramsDialog", "only in B")), palette));
    legend->addStretch();
    return legend;
}

ProgramDiffView::ProgramDiffView(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("programDiffView"));
    setMinimumWidth(400);
    setBackgroundRole(QPalette::Base);
    setAutoFillBackground(true);
}

void ProgramDiffView::setComparison(const CamProgram& a, const CamProgram& b,
                                    const ProgramDiff& diff, const Axis& axis,
                                    const QMap<int, QString>& outputNames) {
    m_a = a;
    m_b = b;
    m_diff = diff;
    m_axis = axis;
    m_names = outputNames;
    m_selected = -1;
    layoutRows();
}

void ProgramDiffView::setFoldUnchanged(bool fold) {
    m_fold = fold;
    layoutRows();
}

void ProgramDiffView::layoutRows() {
    QSet<int> changed;
    for (const CamDifference& d : m_diff.cams) changed.insert(d.output);
    QSet<int> outputs(changed);
    if (!m_fold) {
        for (int output : m_a.tracks.keys())
            if (!m_a.tracks.value(output).cams.isEmpty()) outputs.insert(output);
        for (int output : m_b.tracks.keys())
            if (!m_b.tracks.value(output).cams.isEmpty()) outputs.insert(output);
    }
    m_outputs = outputs.values();
    std::sort(m_outputs.begin(), m_outputs.end());
    setMinimumHeight(kAxisHeight + int(m_outputs.size()) * kRowHeight + 2 * kMargin);
    updateGeometry();
    update();
}

void ProgramDiffView::setSelected(int difference) {
    m_selected = difference;
    update();
}

QSize ProgramDiffView::sizeHint() const {
    return {800, kAxisHeight + int(m_outputs.size()) * kRowHeight + 2 * kMargin};
}

QRect ProgramDiffView::plotArea() const {
    return {kMargin + kLabelWidth, kMargin + kAxisHeight,
            std::max(1, width() - kLabelWidth - 2 * kMargin), int(m_outputs.size()) * kRowHeight};
}

QList<QRectF> ProgramDiffView::differenceRects(int index) const {
    if (index < 0 || index >= m_diff.cams.size()) return {};
    const CamDifference& d = m_diff.cams.at(index);
    const int row = int(m_outputs.indexOf(d.output)) + 1;
    if (row <= 0) return {};
    const DiagramLayout layout = layoutFor(m_axis, plotArea());
    QList<QRectF> rects;
    if (d.camA > 0) rects << layout.camRects(d.a, row);
    if (d.camB > 0) rects << layout.camRects(d.b, row);
    return rects;
}

void ProgramDiffView::paintSwatch(QPainter& painter, const QRectF& rect, Swatch swatch,
                                  const QPalette& palette) {
    painter.save();
    switch (swatch) {
        case Swatch::Same:
            painter.fillRect(rect, palette.color(QPalette::Mid));
            break;
        case Swatch::Changed: {
            // A's extent as a dashed ghost, B's solid and a little lower.
            QPen dashed(palette.color(QPalette::Text), 1, Qt::DashLine);
            painter.setPen(dashed);
            painter.setBrush(Qt::NoBrush);
            painter.drawRect(rect.adjusted(0, 0, -1, -1));
            painter.fillRect(rect.adjusted(rect.width() * 0.25, rect.height() * 0.3, 0, 0),
                             palette.color(QPalette::Highlight));
            break;
        }
        case Swatch::OnlyInA:
            painter.setPen(QPen(kOnlyInA, 2, Qt::DashLine));
            painter.setBrush(QBrush(kOnlyInA, Qt::BDiagPattern));
            painter.drawRect(rect.adjusted(1, 1, -1, -1));
            break;
        case Swatch::OnlyInB:
            painter.setPen(QPen(kOnlyInB, 2));
            painter.setBrush(QBrush(kOnlyInB, Qt::DiagCrossPattern));
            painter.drawRect(rect.adjusted(1, 1, -1, -1));
            break;
    }
    painter.restore();
}

void ProgramDiffView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const QPalette pal = palette();
    const QRect plot = plotArea();
    const DiagramLayout layout = layoutFor(m_axis, plot);
    const QFontMetrics metrics = fontMetrics();

    // Scale.
    const qint64 step = layout.tickStep(80);
    for (qint64 tick = (m_axis.min / step) * step; tick <= m_axis.max; tick += step) {
        if (tick < m_axis.min) continue;
        const double x = layout.xForPosition(double(tick));
        painter.setPen(pal.color(QPalette::Midlight));
        painter.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        painter.setPen(pal.color(QPalette::Text));
        const QString label = QString::number(tick);
        painter.drawText(QPointF(x - metrics.horizontalAdvance(label) / 2.0, plot.top() - 6),
                         label);
    }

    // Cams that are the same in both, per output: those of A no difference names.
    QMap<int, QSet<int>> differingA;
    for (const CamDifference& d : m_diff.cams)
        if (d.camA > 0) differingA[d.output].insert(d.camA);
    for (int r = 0; r < m_outputs.size(); ++r) {
        const int output = m_outputs.at(r);
        const QRectF band = layout.rowBand(r + 1);
        painter.setPen(pal.color(QPalette::Midlight));
        painter.drawLine(QPointF(plot.left(), band.bottom()), QPointF(plot.right(), band.bottom()));
        painter.setPen(pal.color(QPalette::Text));
        const QString label = QStringLiteral("%1  %2").arg(output).arg(m_names.value(output));
        painter.drawText(QRectF(kMargin, band.top(), kLabelWidth - 6, band.height()),
                         Qt::AlignVCenter | Qt::AlignLeft,
                         metrics.elidedText(label, Qt::ElideRight, kLabelWidth - 6));
        const QList<Cam> cams = m_a.tracks.value(output).cams;
        for (int i = 0; i < cams.size(); ++i) {
            if (differingA.value(output).contains(i + 1)) continue;
            for (const QRectF& bar : layout.camRects(cams.at(i), r + 1))
                paintSwatch(painter, bar, Swatch::Same, pal);
        }
    }

    // The differences over them.
    for (int index = 0; index < m_diff.cams.size(); ++index) {
        const CamDifference& d = m_diff.cams.at(index);
        const int row = int(m_outputs.indexOf(d.output)) + 1;
        if (row <= 0) continue;
        switch (d.kind) {
            case CamDifference::Kind::OnlyInA:
                for (const QRectF& bar : layout.camRects(d.a, row))
                    paintSwatch(painter, bar, Swatch::OnlyInA, pal);
                break;
            case CamDifference::Kind::OnlyInB:
                for (const QRectF& bar : layout.camRects(d.b, row))
                    paintSwatch(painter, bar, Swatch::OnlyInB, pal);
                break;
            case CamDifference::Kind::Changed: {
                painter.setPen(QPen(pal.color(QPalette::Text), 1, Qt::DashLine));
                painter.setBrush(Qt::NoBrush);
                for (const QRectF& ghost : layout.camRects(d.a, row))
                    painter.drawRect(ghost.adjusted(0, 0, -1, -1));
                for (const QRectF& bar : layout.camRects(d.b, row))
                    painter.fillRect(bar.adjusted(0, bar.height() * 0.3, 0, 0),
                                     pal.color(QPalette::Highlight));
                // The edges that moved: a mark at B's edge, and a triangle above it.
                const QRectF band = layout.rowBand(row);
                painter.setPen(QPen(kMovedEdge, 2));
                painter.setBrush(kMovedEdge);
                for (const auto& [moved, at] : {std::pair{d.a.on != d.b.on, d.b.on},
                                                std::pair{d.a.off != d.b.off, d.b.off}}) {
                    if (!moved) continue;
                    const double x = layout.xForPosition(double(at));
                    painter.drawLine(QPointF(x, band.top() + 2), QPointF(x, band.bottom() - 2));
                    painter.drawPolygon(QPolygonF{QPointF(x - 4, band.top() + 1),
                                                  QPointF(x + 4, band.top() + 1),
                                                  QPointF(x, band.top() + 7)});
                }
                break;
            }
        }
    }

    if (m_selected >= 0) {
        QPen focus(pal.color(QPalette::Text), 2, Qt::DotLine);
        painter.setPen(focus);
        painter.setBrush(Qt::NoBrush);
        for (const QRectF& rect : differenceRects(m_selected))
            painter.drawRect(rect.adjusted(-3, -3, 3, 3));
    }
    painter.setPen(pal.color(QPalette::Mid));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(plot);
}

void ProgramDiffView::mousePressEvent(QMouseEvent* event) {
    const QPointF at = event->position();
    for (int index = 0; index < m_diff.cams.size(); ++index) {
        for (const QRectF& rect : differenceRects(index)) {
            if (rect.adjusted(-3, -3, 3, 3).contains(at)) {
                setSelected(index);
                Q_EMIT differenceClicked(index);
                return;
            }
        }
    }
    QWidget::mousePressEvent(event);
}

void ProgramDiffView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    update();
}

}  // namespace cambench
