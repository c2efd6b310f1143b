#include "ui/camcon/cameditor/cam_diagram_widget.h"

#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/cameditor/editor_colors.h"
#include "ui/camcon/cameditor/timing_text.h"

#include <QEvent>
#include <QHelpEvent>
#include <QKeyEvent>
#include <QLocale>
#include <QMouseEvent>
#include <QPainter>
#include <QScrollBar>
#include <QSet>
#include <QToolTip>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace cambench {

namespace {

constexpr int kScrollSteps = 10000;  // horizontal scroll bar resolution over the whole axis
constexpr double kEdgeGrip = 4.0;    // pixels either side of a cam edge that resize it
constexpr double kZoomStep = 1.5;
constexpr double kScaleTickPixels = 90.0;

// Status colours read well on light and dark backgrounds alike; everything
// else comes from the palette.
const QColor kLiveColor(255, 140, 0);
const QColor kLedOnColor(40, 200, 60);
// The electrical on-times: a teal apart from the palette's highlight, the
// live cursor's orange and the error red, outlined so it reads on both.
const QColor kTimingColor(0, 150, 160);

QColor withAlpha(QColor color, int alpha) {
    color.setAlpha(alpha);
    return color;
}

}  // namespace

CamDiagramWidget::CamDiagramWidget(CamDocument* document, QWidget* parent)
    : QWidget(parent),
      m_document(document),
      m_horizontal(new QScrollBar(Qt::Horizontal, this)),
      m_vertical(new QScrollBar(Qt::Vertical, this)) {
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setAttribute(Qt::WA_OpaquePaintEvent);
    m_layout.setAxis(document->axis());

    connect(m_horizontal, &QScrollBar::valueChanged, this, [this](int value) {
        const Axis& axis = m_layout.axis();
        m_layout.setViewStart(axis.min + double(value) / kScrollSteps * double(axis.span()));
        update();
    });
    connect(m_vertical, &QScrollBar::valueChanged, this, [this] {
        updateLayout();
        update();
    });
    connect(document, &CamDocument::limitsChanged, this, [this] {
        m_layout.setAxis(m_document->axis());
        updateLayout();
        update();
    });
    const auto repaint = [this] { update(); };
    connect(document, &CamDocument::trackChanged, this, repaint);
    connect(document, &CamDocument::programChanged, this, repaint);
    connect(document, &CamDocument::outputNameChanged, this, repaint);
    connect(document, &CamDocument::deviceStateChanged, this, repaint);
    updateLayout();
}

QSize CamDiagramWidget::sizeHint() const {
    return {labelWidth() + 600, scaleHeight() + 12 * rowHeight()};
}

QSize CamDiagramWidget::minimumSizeHint() const {
    return {labelWidth() + 150, scaleHeight() + 3 * rowHeight()};
}

int CamDiagramWidget::labelWidth() const {
    return fontMetrics().horizontalAdvance(QLatin1Char('M')) * 14 + rowHeight();
}

int CamDiagramWidget::rowHeight() const {
    return fontMetrics().height() + 10 + (m_timingShown ? stripHeight() : 0);
}

int CamDiagramWidget::stripHeight() const {
    return fontMetrics().height() + 4;
}

int CamDiagramWidget::scaleHeight() const {
    return fontMetrics().height() + 12;
}

void CamDiagramWidget::updateLayout() {
    const int scrollBarHeight = m_horizontal->sizeHint().height();
    const int scrollBarWidth = m_vertical->sizeHint().width();
    const int rowsHeight = m_document->outputCount() * rowHeight();
    const int availableHeight = height() - scaleHeight() - scrollBarHeight;
    const bool needVertical = rowsHeight > availableHeight;
    m_vertical->setVisible(needVertical);
    const int right = width() - (needVertical ? scrollBarWidth : 0);
    const QRect plot(labelWidth(), scaleHeight(), std::max(right - labelWidth(), 1),
                     std::max(availableHeight, 1));
    m_horizontal->setGeometry(plot.left(), plot.bottom() + 1, plot.width(), scrollBarHeight);
    m_vertical->setGeometry(right, plot.top(), scrollBarWidth, plot.height());
    {
        const QSignalBlocker blocker(m_vertical);
        m_vertical->setRange(0, needVertical ? rowsHeight - availableHeight : 0);
        m_vertical->setPageStep(plot.height());
        m_vertical->setSingleStep(rowHeight());
    }
    m_layout.setStripHeight(m_timingShown ? stripHeight() : 0);
    m_layout.setPlotArea(plot, rowHeight(), m_vertical->value());
    syncScrollBars();
}

void CamDiagramWidget::syncScrollBars() {
    const double span = double(m_layout.axis().span());
    const int page = int(std::lround(kScrollSteps * m_layout.viewSpan() / span));
    const QSignalBlocker blocker(m_horizontal);
    m_horizontal->setRange(0, kScrollSteps - page);
    m_horizontal->setPageStep(page);
    m_horizontal->setSingleStep(std::max(page / 10, 1));
    m_horizontal->setValue(
        int(std::lround((m_layout.viewStart() - m_layout.axis().min) / span * kScrollSteps)));
}

void CamDiagramWidget::setProgram(int program) {
    m_program = program;
    m_selectedCam = -1;
    update();
}

void CamDiagramWidget::setSelection(int output, int cam) {
    m_selectedOutput = output;
    m_selectedCam = cam;
    ensureOutputVisible(output);
    update();
}

void CamDiagramWidget::ensureOutputVisible(int output) {
    const QRectF band = m_layout.rowBand(output);
    const QRect plot = m_layout.plotArea();
    if (band.top() < plot.top()) {
        m_vertical->setValue(m_vertical->value() - int(plot.top() - band.top()));
    } else if (band.bottom() > plot.bottom() + 1) {
        m_vertical->setValue(m_vertical->value() + int(band.bottom() - plot.bottom() - 1));
    }
}

void CamDiagramWidget::zoomIn() {
    m_layout.zoom(kZoomStep, m_layout.viewStart() + m_layout.viewSpan() / 2);
    syncScrollBars();
    update();
}

void CamDiagramWidget::zoomOut() {
    m_layout.zoom(1.0 / kZoomStep, m_layout.viewStart() + m_layout.viewSpan() / 2);
    syncScrollBars();
    update();
}

void CamDiagramWidget::zoomFit() {
    m_layout.fit();
    syncScrollBars();
    update();
}

void CamDiagramWidget::setLivePosition(qint32 position) {
    m_live = true;
    m_livePosition = position;
    update();
}

void CamDiagramWidget::setOutputStates(const QList<bool>& states) {
    m_live = true;
    m_outputStates = states;
    update();
}

void CamDiagramWidget::clearLive() {
    m_live = false;
    m_outputStates.clear();
    update();
}

void CamDiagramWidget::setTiming(const QList<OutputTiming>& outputs, const QString& speed) {
    const bool grows = !m_timingShown;
    m_timingShown = true;
    m_timing.clear();
    for (const OutputTiming& timing : outputs) m_timing.insert(timing.output, timing);
    m_timingSpeed = speed;
    if (grows) updateLayout();
    update();
}

void CamDiagramWidget::clearTiming() {
    if (!m_timingShown) return;
    m_timingShown = false;
    m_timing.clear();
    updateLayout();
    update();
}

QList<QRectF> CamDiagramWidget::timingRects(int output, int cam) const {
    const OutputTiming timing = m_timing.value(output);
    if (cam < 0 || cam >= timing.cams.size()) return {};
    const TimedCam& timed = timing.cams.at(cam);
    return m_layout.stripRects(timed.on, std::max(timed.length, 0.0), output);
}

QList<QRectF> CamDiagramWidget::camRects(int output, int index) const {
    const QList<Cam> cams = m_document->track(m_program, output).cams;
    if (index < 0 || index >= cams.size()) {
        return {};
    }
    return m_layout.camRects(cams.at(index), output);
}

DiagramHit CamDiagramWidget::hitTest(const QPoint& point) const {
    DiagramHit hit;
    const QRect plot = m_layout.plotArea();
    if (point.x() < plot.left() || point.x() > plot.right()) {
        return hit;
    }
    hit.output = m_layout.outputAtY(point.y(), m_document->outputCount());
    if (hit.output == 0) {
        return hit;
    }
    hit.part = DiagramHit::Row;
    const QList<Cam> cams = m_document->track(m_program, hit.output).cams;
    // Last drawn is on top: search backwards.
    for (int index = int(cams.size()) - 1; index >= 0; --index) {
        const Cam& cam = cams.at(index);
        const QList<QRectF> rects = m_layout.camRects(cam, hit.output);
        double width = 0;
        bool inside = false;
        for (const QRectF& rect : rects) {
            width += rect.width();
            inside = inside || rect.adjusted(-kEdgeGrip, 0, kEdgeGrip, 0).contains(point);
        }
        if (!inside) {
            continue;
        }
        hit.cam = index;
        // Narrow bars keep a body to grab between their edge grips.
        const double grip = std::min(kEdgeGrip, width / 3);
        if (std::abs(point.x() - m_layout.xForPosition(cam.on)) <= grip) {
            hit.part = DiagramHit::OnEdge;
        } else if (std::abs(point.x() - m_layout.xForPosition(cam.off)) <= grip) {
            hit.part = DiagramHit::OffEdge;
        } else if (std::any_of(rects.cbegin(), rects.cend(),
                               [&](const QRectF& rect) { return rect.contains(point); })) {
            hit.part = DiagramHit::Body;
        } else {
            hit.cam = -1;
            continue;
        }
        return hit;
    }
    return hit;
}

void CamDiagramWidget::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) {
        QWidget::mousePressEvent(event);
        return;
    }
    const QPoint point = event->position().toPoint();
    const DiagramHit hit = hitTest(point);
    m_pressPosition = m_layout.positionAtX(point.x());
    m_pressViewStart = m_layout.viewStart();
    if (hit.cam >= 0) {
        m_drag = hit.part == DiagramHit::OnEdge    ? Drag::OnEdge
                 : hit.part == DiagramHit::OffEdge ? Drag::OffEdge
                                                   : Drag::Cam;
        m_dragOutput = hit.output;
        m_dragCam = hit.cam;
        m_dragOrigin = m_document->track(m_program, hit.output).cams.at(hit.cam);
        m_dragKey = m_document->newDragKey();
    } else if (m_layout.plotArea().contains(point)) {
        m_drag = Drag::Pan;
        setCursor(Qt::ClosedHandCursor);
    }
    if (hit.output > 0) {
        setSelection(hit.output, hit.cam);
        Q_EMIT camSelected(hit.output, hit.cam);
    }
}

void CamDiagramWidget::mouseMoveEvent(QMouseEvent* event) {
    const QPoint point = event->position().toPoint();
    if (m_drag == Drag::None) {
        const DiagramHit hit = hitTest(point);
        if (hit.part == DiagramHit::OnEdge || hit.part == DiagramHit::OffEdge) {
            setCursor(Qt::SizeHorCursor);
        } else if (hit.part == DiagramHit::Body) {
            setCursor(Qt::OpenHandCursor);
        } else {
            unsetCursor();
        }
        return;
    }
    if (m_drag == Drag::Pan) {
        const double moved = m_layout.positionAtX(point.x()) - m_pressPosition;
        m_layout.setViewStart(m_layout.viewStart() - moved);
        m_pressPosition = m_layout.positionAtX(point.x());
        syncScrollBars();
        update();
        return;
    }
    dragCamTo(m_layout.positionAtX(point.x()));
}

void CamDiagramWidget::dragCamTo(double position) {
    const qint64 delta = std::llround(position - m_pressPosition);
    const Axis& axis = m_layout.axis();
    Cam cam = m_dragOrigin;
    switch (m_drag) {
        case Drag::Cam:
            cam = axis.shifted(m_dragOrigin, delta);
            break;
        case Drag::OnEdge:
            cam.on = axis.moved(m_dragOrigin.on, delta);
            break;
        case Drag::OffEdge:
            cam.off = axis.moved(m_dragOrigin.off, delta);
            break;
        default:
            return;
    }
    m_document->setCam(m_program, m_dragOutput, m_dragCam, cam, m_dragKey);
    // The track stays ordered by switch-on point, so the cam may have a new index.
    const int index = int(m_document->track(m_program, m_dragOutput).cams.indexOf(cam));
    if (index >= 0 && index != m_dragCam) {
        m_dragCam = index;
        setSelection(m_dragOutput, index);
        Q_EMIT camSelected(m_dragOutput, index);
    }
}

void CamDiagramWidget::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton && m_drag != Drag::None) {
        if (m_drag != Drag::Pan) {
            dragCamTo(m_layout.positionAtX(event->position().x()));
        }
        m_drag = Drag::None;
        unsetCursor();
    }
}

void CamDiagramWidget::wheelEvent(QWheelEvent* event) {
    const QPoint delta = event->angleDelta();
    if (event->modifiers() & Qt::ControlModifier) {
        const double anchor = m_layout.positionAtX(event->position().x());
        m_layout.zoom(std::pow(kZoomStep, delta.y() / 120.0), anchor);
        syncScrollBars();
        update();
    } else if (delta.x() != 0 || (event->modifiers() & Qt::ShiftModifier) ||
               !m_vertical->isVisible()) {
        const int steps = delta.x() != 0 ? delta.x() : delta.y();
        m_layout.setViewStart(m_layout.viewStart() - steps / 120.0 * m_layout.viewSpan() / 10);
        syncScrollBars();
        update();
    } else {
        m_vertical->setValue(m_vertical->value() - delta.y() / 120 * rowHeight());
    }
    event->accept();
}

void CamDiagramWidget::keyPressEvent(QKeyEvent* event) {
    switch (event->key()) {
        case Qt::Key_Plus:
        case Qt::Key_Equal:
            zoomIn();
            break;
        case Qt::Key_Minus:
            zoomOut();
            break;
        case Qt::Key_0:
            zoomFit();
            break;
        case Qt::Key_Left:
        case Qt::Key_Right: {
            const double step = m_layout.viewSpan() / 10 * (event->key() == Qt::Key_Left ? -1 : 1);
            m_layout.setViewStart(m_layout.viewStart() + step);
            syncScrollBars();
            update();
            break;
        }
        case Qt::Key_Up:
        case Qt::Key_Down: {
            const int output = std::clamp(m_selectedOutput + (event->key() == Qt::Key_Up ? -1 : 1),
                                          1, std::max(m_document->outputCount(), 1));
            setSelection(output, -1);
            Q_EMIT camSelected(output, -1);
            break;
        }
        default:
            QWidget::keyPressEvent(event);
    }
}

bool CamDiagramWidget::event(QEvent* event) {
    if (event->type() == QEvent::ToolTip) {
        auto* help = static_cast<QHelpEvent*>(event);
        const DiagramHit hit = hitTest(help->pos());
        const QString timing = timingToolTipAt(help->pos());
        if (hit.cam >= 0) {
            QToolTip::showText(help->globalPos(), camToolTip(hit.output, hit.cam), this);
        } else if (!timing.isEmpty()) {
            QToolTip::showText(help->globalPos(), timing, this);
        } else {
            QToolTip::hideText();
            event->ignore();
        }
        return true;
    }
    return QWidget::event(event);
}

void CamDiagramWidget::changeEvent(QEvent* event) {
    if (event->type() == QEvent::FontChange || event->type() == QEvent::PaletteChange) {
        updateLayout();
        update();
    }
    QWidget::changeEvent(event);
}

void CamDiagramWidget::resizeEvent(QResizeEvent*) {
    updateLayout();
}

QString CamDiagramWidget::camToolTip(int output, int cam) const {
    const Track track = m_document->track(m_program, output);
    const Cam& value = track.cams.at(cam);
    QString text = tr("Output %1, cam %2: on %3, off %4, length %5")
                       .arg(output)
                       .arg(cam + 1)
                       .arg(value.on)
                       .arg(value.off)
                       .arg(m_layout.axis().length(value));
    for (const CamProblem& problem : m_document->problems(m_program, output)) {
        if (problem.cam == cam) {
            text += QLatin1Char('\n') + problem.message;
        }
    }
    if (m_document->camState(m_program, output, cam) == ChangeState::Edited) {
        text += QLatin1Char('\n') + tr("Changed, not yet written to the device.");
    }
    return text;
}

QString CamDiagramWidget::timingToolTipAt(const QPoint& point) const {
    if (!m_timingShown) return {};
    const int output = m_layout.outputAtY(point.y(), m_document->outputCount());
    const OutputTiming timing = m_timing.value(output);
    if (output == 0 || timing.cams.isEmpty()) return {};
    QStringList lines;
    if (point.x() < m_layout.plotArea().left()) {
        // The row's label: what breaks on this output at this speed, and
        // the speed above which it first breaks.
        for (const TimingProblem& problem : timing.problems)
            lines << timingProblemText(output, problem, m_layout.axis());
        if (lines.isEmpty() && timing.firstLimit)
            lines << tr("At %1 output %2 switches as drawn. First limit: %3")
                         .arg(m_timingSpeed)
                         .arg(output)
                         .arg(timingProblemText(output, *timing.firstLimit, m_layout.axis()));
        return lines.join(QLatin1Char('\n'));
    }
    for (int cam = 0; cam < timing.cams.size(); ++cam) {
        const QList<QRectF> rects = timingRects(output, cam);
        if (std::any_of(rects.cbegin(), rects.cend(), [&](const QRectF& rect) {
                return rect.adjusted(-kEdgeGrip, 0, kEdgeGrip, 0).contains(point);
            }))
            return timingToolTip(output, cam);
    }
    return {};
}

QString CamDiagramWidget::timingToolTip(int output, int cam) const {
    const OutputTiming timing = m_timing.value(output);
    const TimedCam& timed = timing.cams.at(cam);
    const QLocale locale;
    QString text;
    if (timed.length <= 0) {
        text = tr("Output %1, cam %2 at %3: never switches on (it vanishes).")
                   .arg(output)
                   .arg(timed.number)
                   .arg(m_timingSpeed);
    } else {
        text = tr("Output %1, cam %2 at %3: switches on at %4, off at %5")
                   .arg(output)
                   .arg(timed.number)
                   .arg(m_timingSpeed, locale.toString(timed.on, 'f', 1),
                        locale.toString(timed.off, 'f', 1));
        if (timed.durationMs)
            text += QLatin1Char('\n') + tr("On for %1.").arg(durationText(*timed.durationMs));
    }
    text += QLatin1Char('\n') +
            tr("Programmed: on %1, off %2; dead time %3 on, %4 off.")
                .arg(timed.programmed.on)
                .arg(timed.programmed.off)
                .arg(durationText(timing.onDeadTimeMs), durationText(timing.offDeadTimeMs));
    for (const TimingProblem& problem : timing.problems) {
        if (problem.cam == timed.number || problem.nextCam == timed.number)
            text += QLatin1Char('\n') + timingProblemText(output, problem, m_layout.axis());
    }
    return text;
}

void CamDiagramWidget::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), palette().color(QPalette::Window));
    paintRows(painter);
    paintScale(painter);
    paintLiveCursor(painter);
}

void CamDiagramWidget::paintRows(QPainter& painter) const {
    const QRect plot = m_layout.plotArea();
    const QPalette& pal = palette();
    const qint64 step = m_layout.tickStep(kScaleTickPixels);
    painter.save();
    painter.setClipRect(QRect(0, plot.top(), plot.right() + 1, plot.height()));
    for (int output = 1; output <= m_document->outputCount(); ++output) {
        const QRectF band = m_layout.rowBand(output);
        if (band.bottom() < plot.top() || band.top() > plot.bottom()) {
            continue;
        }
        const QRectF plotBand(plot.left(), band.top(), plot.width(), band.height());
        painter.fillRect(plotBand,
                         pal.color(output % 2 ? QPalette::Base : QPalette::AlternateBase));
        if (output == m_selectedOutput) {
            painter.fillRect(plotBand, withAlpha(pal.color(QPalette::Highlight), 40));
        }
        paintLabel(painter, output);
    }
    // Grid lines at the scale's ticks, under the cams, only as far as there are rows.
    const double rowsBottom = m_layout.rowBand(m_document->outputCount()).bottom();
    painter.setClipRect(QRectF(plot).intersected(
        QRectF(plot.left(), plot.top(), plot.width(), rowsBottom - plot.top())));
    painter.setPen(withAlpha(pal.color(QPalette::Text), 40));
    const double end = m_layout.viewStart() + m_layout.viewSpan();
    for (double tick = std::ceil(m_layout.viewStart() / step) * step; tick <= end; tick += step) {
        const double x = m_layout.xForPosition(tick);
        painter.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
    }
    for (int output = 1; output <= m_document->outputCount(); ++output) {
        const QRectF band = m_layout.rowBand(output);
        if (band.bottom() >= plot.top() && band.top() <= plot.bottom()) {
            paintCams(painter, output);
            if (m_timingShown) paintTiming(painter, output);
        }
    }
    painter.restore();
}

void CamDiagramWidget::paintLabel(QPainter& painter, int output) const {
    const QPalette& pal = palette();
    const QRectF band = m_layout.rowBand(output);
    const QRectF label(0, band.top(), m_layout.plotArea().left(), band.height());
    painter.fillRect(
        label, pal.color(output == m_selectedOutput ? QPalette::Highlight : QPalette::Button));
    // The LED keeps its size when the timing strip makes the row taller.
    const double led = (band.height() - m_layout.stripHeight()) * 0.45;
    const QRectF ledRect(4, band.top() + (band.height() - m_layout.stripHeight() - led) / 2, led,
                         led);
    if (m_live) {
        const bool on = output - 1 < m_outputStates.size() && m_outputStates.at(output - 1);
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setPen(pal.color(QPalette::Mid));
        painter.setBrush(on ? kLedOnColor : pal.color(QPalette::Window));
        painter.drawEllipse(ledRect);
        painter.setRenderHint(QPainter::Antialiasing, false);
    }
    QRectF textRect = label.adjusted(ledRect.right() + 6, 0, -4, 0);
    if (m_timingShown && !m_timing.value(output).problems.isEmpty()) {
        // A red triangle with "!" at the label's end: this output's picture
        // breaks at the speed shown (the tool tip says how).
        const double size = std::min(band.height() - 6, double(fontMetrics().height()));
        const QRectF mark(textRect.right() - size, band.center().y() - size / 2, size, size);
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setPen(QPen(Qt::white, 1));
        painter.setBrush(errorColor());
        painter.drawPolygon(QPolygonF(
            {QPointF(mark.center().x(), mark.top()), mark.bottomRight(), mark.bottomLeft()}));
        painter.setRenderHint(QPainter::Antialiasing, false);
        painter.setPen(Qt::white);
        painter.drawText(mark.adjusted(0, size * 0.2, 0, 0), Qt::AlignCenter, QStringLiteral("!"));
        textRect.setRight(mark.left() - 3);
    }
    const QString name = m_document->outputName(output);
    const QString text =
        name.isEmpty() ? QString::number(output) : tr("%1  %2").arg(output).arg(name);
    painter.setPen(
        pal.color(output == m_selectedOutput ? QPalette::HighlightedText : QPalette::ButtonText));
    painter.drawText(textRect, Qt::AlignVCenter | Qt::AlignLeft,
                     fontMetrics().elidedText(text, Qt::ElideRight, int(textRect.width())));
    painter.setPen(pal.color(QPalette::Mid));
    painter.drawLine(QPointF(0, band.bottom()),
                     QPointF(m_layout.plotArea().right(), band.bottom()));
}

void CamDiagramWidget::paintCams(QPainter& painter, int output) const {
    const QPalette& pal = palette();
    const Track track = m_document->track(m_program, output);
    QSet<int> invalid;
    for (const CamProblem& problem : m_document->problems(m_program, output)) {
        invalid.insert(problem.cam);
    }
    for (int index = 0; index < track.cams.size(); ++index) {
        const bool edited = m_document->camState(m_program, output, index) == ChangeState::Edited;
        const bool selected = output == m_selectedOutput && index == m_selectedCam;
        const QColor fill = invalid.contains(index) ? errorColor() : pal.color(QPalette::Highlight);
        const QColor text =
            invalid.contains(index) ? QColor(Qt::white) : pal.color(QPalette::HighlightedText);
        for (const QRectF& rect : m_layout.camRects(track.cams.at(index), output)) {
            painter.fillRect(rect, fill);
            if (edited) {
                // Hatched and outlined: not yet written to the device.
                painter.fillRect(rect, QBrush(withAlpha(text, 110), Qt::BDiagPattern));
                painter.setPen(QPen(pal.color(QPalette::Text), 1.5, Qt::DashLine));
                painter.setBrush(Qt::NoBrush);
                painter.drawRect(rect.adjusted(0.75, 0.75, -0.75, -0.75));
            }
            if (selected) {
                painter.setPen(QPen(pal.color(QPalette::Text), 2.5));
                painter.setBrush(Qt::NoBrush);
                painter.drawRect(rect.adjusted(-1, -1, 1, 1));
            }
            const QString number = QString::number(index + 1);
            if (rect.width() > fontMetrics().horizontalAdvance(number) + 6) {
                painter.setPen(text);
                painter.drawText(rect, Qt::AlignCenter, number);
            }
        }
    }
}

void CamDiagramWidget::paintTiming(QPainter& painter, int output) const {
    const OutputTiming timing = m_timing.value(output);
    if (timing.cams.isEmpty()) return;
    const QPalette& pal = palette();
    const Track track = m_document->track(m_program, output);
    QSet<int> troubled;  // cams in a problem at this speed
    for (const TimingProblem& problem : timing.problems) {
        if (problem.kind == TimingProblem::Kind::ShiftOverCycle) continue;
        troubled << problem.cam << problem.nextCam;
    }
    const QRectF band = m_layout.rowBand(output);
    const double stripTop = band.bottom() - m_layout.stripHeight();
    for (int cam = 0; cam < timing.cams.size(); ++cam) {
        const TimedCam& timed = timing.cams.at(cam);
        const bool trouble = troubled.contains(timed.number);
        // From the programmed switch-on edge down to where it switches.
        if (cam < track.cams.size() && timing.shiftOn > 0) {
            const double from = m_layout.xForPosition(track.cams.at(cam).on);
            const double to = m_layout.xForPosition(timed.on);
            if (std::abs(from - to) < m_layout.plotArea().width() / 2.0) {
                painter.setPen(QPen(pal.color(QPalette::Text), 1, Qt::DotLine));
                painter.drawLine(QPointF(from, stripTop - 2), QPointF(to, stripTop + 2));
            }
        }
        if (timed.length <= 0) {
            // Vanished: a red cross where it would switch on.
            const double x = m_layout.xForPosition(timed.on);
            const double h = m_layout.stripHeight() / 2.0 - 1;
            const double y = stripTop + m_layout.stripHeight() / 2.0;
            painter.setPen(QPen(errorColor(), 2.5));
            painter.drawLine(QPointF(x - h, y - h), QPointF(x + h, y + h));
            painter.drawLine(QPointF(x - h, y + h), QPointF(x + h, y - h));
            continue;
        }
        const QString duration = timed.durationMs ? durationText(*timed.durationMs) : QString();
        for (const QRectF& rect : timingRects(output, cam)) {
            painter.fillRect(rect, trouble ? errorColor() : kTimingColor);
            if (trouble)
                painter.fillRect(rect, QBrush(withAlpha(Qt::white, 120), Qt::Dense6Pattern));
            painter.setPen(QPen(pal.color(QPalette::Text), 1));
            painter.setBrush(Qt::NoBrush);
            painter.drawRect(rect.adjusted(0.5, 0.5, -0.5, -0.5));
            if (!duration.isEmpty() &&
                rect.width() > fontMetrics().horizontalAdvance(duration) + 6) {
                painter.setPen(Qt::white);
                painter.drawText(rect, Qt::AlignCenter, duration);
            }
        }
    }
}

void CamDiagramWidget::paintScale(QPainter& painter) const {
    const QPalette& pal = palette();
    const QRect plot = m_layout.plotArea();
    const QRect scale(0, 0, width(), plot.top());
    painter.fillRect(scale, pal.color(QPalette::Window));
    painter.setPen(pal.color(QPalette::WindowText));
    painter.drawText(QRect(4, 0, plot.left() - 8, plot.top() - 2), Qt::AlignLeft | Qt::AlignBottom,
                     tr("Output"));
    painter.save();
    // Labels may reach a little past the plot's ends, ticks may not.
    painter.setClipRect(QRect(plot.left() - 20, 0, plot.width() + 40, plot.top()));
    const qint64 step = m_layout.tickStep(kScaleTickPixels);
    const qint64 minor = step >= 5 ? step / 5 : 1;
    const double end = m_layout.viewStart() + m_layout.viewSpan();
    const int base = plot.top() - 1;
    painter.drawLine(plot.left(), base, plot.right(), base);
    for (double tick = std::ceil(m_layout.viewStart() / minor) * minor; tick < end; tick += minor) {
        const double x = m_layout.xForPosition(tick);
        const bool major = std::fmod(tick, double(step)) == 0.0;
        painter.drawLine(QPointF(x, base), QPointF(x, base - (major ? 6 : 3)));
        if (major) {
            const QString label = QString::number(qint64(tick));
            const double width = fontMetrics().horizontalAdvance(label) + 4;
            // Keep labels at the ends inside the widget instead of cutting them.
            const double left = std::clamp(x - width / 2, double(plot.left()) - 2,
                                           double(plot.right()) + 2 - width);
            painter.drawText(QRectF(left, 0, width, base - 6), Qt::AlignHCenter | Qt::AlignBottom,
                             label);
        }
    }
    painter.restore();
}

void CamDiagramWidget::paintLiveCursor(QPainter& painter) const {
    if (!m_live) {
        return;
    }
    const QRect plot = m_layout.plotArea();
    const double x = m_layout.xForPosition(m_livePosition + 0.5);
    if (x < plot.left() || x > plot.right()) {
        return;
    }
    const double rowsBottom = m_layout.rowBand(m_document->outputCount()).bottom();
    painter.setPen(QPen(kLiveColor, 2));
    painter.drawLine(QPointF(x, plot.top() - 8),
                     QPointF(x, std::min(rowsBottom, double(plot.bottom()))));
}

}  // namespace cambench
