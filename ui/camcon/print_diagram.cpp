#include "print_diagram.h"

#include "ui/camcon/cameditor/cam_document.h"
#include "ui/camcon/cameditor/diagram_layout.h"

#include <QCoreApplication>
#include <QFontMetrics>
#include <QPainter>

namespace cambench {

namespace {
constexpr int kRowHeight = 30;
constexpr int kAxisHeight = 50;
constexpr int kMargin = 8;
const QColor kCam(0x2f, 0x5f, 0x9e);
const QColor kEdited(0xc0, 0x4a, 0x1e);
}  // namespace

QImage printDiagram(const CamDocument& cams, int program, int first, int last, int width) {
    const int rows = std::max(0, last - first + 1);
    QImage image(width, kAxisHeight + rows * kRowHeight + 2 * kMargin, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    QFont font = painter.font();
    font.setPixelSize(20);
    painter.setFont(font);
    const QFontMetrics metrics(font);
    const int labelWidth =
        metrics.horizontalAdvance(QStringLiteral("000 ")) + metrics.averageCharWidth() * 16;

    DiagramLayout layout;
    layout.setAxis(cams.axis());
    const QRect plot(kMargin + labelWidth, kMargin + kAxisHeight, width - labelWidth - 2 * kMargin,
                     rows * kRowHeight);
    // The layout counts rows from output 1: shift so that `first` is on top.
    layout.setPlotArea(plot, kRowHeight, (first - 1) * kRowHeight);
    layout.fit();

    // Axis with ticks, about 80 px apart.
    painter.setPen(Qt::black);
    painter.drawLine(plot.left(), plot.top(), plot.right(), plot.top());
    const qint64 step = layout.tickStep(110);
    const Axis axis = cams.axis();
    for (qint64 tick = (axis.min / step) * step; tick <= axis.max; tick += step) {
        if (tick < axis.min) continue;
        const double x = layout.xForPosition(double(tick));
        painter.setPen(QColor(0xc8, 0xc8, 0xc8));
        painter.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        painter.setPen(Qt::black);
        painter.drawLine(QPointF(x, plot.top() - 8), QPointF(x, plot.top()));
        const QString label = QString::number(tick);
        painter.drawText(QPointF(x - metrics.horizontalAdvance(label) / 2.0, plot.top() - 10),
                         label);
    }

    for (int output = first; output <= last; ++output) {
        const QRectF band = layout.rowBand(output);
        const QRectF row(plot.left(), band.top(), plot.width(), band.height());
        painter.setPen(QColor(0xe0, 0xe0, 0xe0));
        painter.drawLine(row.bottomLeft(), row.bottomRight());
        const bool edited = cams.trackState(program, output) == ChangeState::Edited;
        QString label = QStringLiteral("%1 %2").arg(output, 3).arg(cams.outputName(output));
        painter.setPen(edited ? kEdited : Qt::black);
        painter.drawText(QRectF(kMargin, row.top(), labelWidth - 4, row.height()),
                         Qt::AlignVCenter | Qt::AlignLeft,
                         metrics.elidedText(label, Qt::ElideRight, labelWidth - 4));
        for (const Cam& cam : cams.track(program, output).cams) {
            for (QRectF bar : layout.camRects(cam, output)) {
                bar = bar.intersected(row.adjusted(0, 5, 0, -5));
                painter.fillRect(bar, edited ? kEdited : kCam);
                if (edited) {
                    painter.fillRect(bar, QBrush(Qt::white, Qt::BDiagPattern));
                }
            }
        }
    }
    painter.setPen(Qt::black);
    painter.drawRect(plot);
    return image;
}

}  // namespace cambench
