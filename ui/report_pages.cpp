#include "report_pages.h"

#include <QAbstractTextDocumentLayout>
#include <QCoreApplication>
#include <QDateTime>
#include <QPageSize>
#include <QPagedPaintDevice>
#include <QPainter>
#include <QPalette>
#include <QPdfWriter>
#include <QSaveFile>
#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocument>
#include <cmath>

namespace cambench {

namespace {
// A heading that starts below this part of its page moves to the next page.
constexpr double kHeadingFoot = 0.8;
}  // namespace

QString reportTime(const QDateTime& time) {
    return time.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm"));
}

QString reportParagraph(const QString& text) {
    return QStringLiteral("<p>%1</p>").arg(text.toHtmlEscaped());
}

QString reportHeading(const QString& text) {
    return QStringLiteral("<h2>%1</h2>").arg(text.toHtmlEscaped());
}

QString reportTable(const QStringList& head, const QList<QStringList>& rows) {
    const auto row = [](const QStringList& cells, QLatin1String tag) {
        QString html = QStringLiteral("<tr>");
        for (const QString& cell : cells)
            html += QStringLiteral("<%1>%2</%1>").arg(tag, cell.toHtmlEscaped());
        return html + QStringLiteral("</tr>");
    };
    QString html = QStringLiteral("<table border='1' cellspacing='0' cellpadding='3'>");
    if (!head.isEmpty()) html += row(head, QLatin1String("th"));
    for (const QStringList& cells : rows) html += row(cells, QLatin1String("td"));
    return html + QStringLiteral("</table>");
}

int keepHeadingsWithText(QTextDocument& document) {
    const qreal pageHeight = document.pageSize().height();
    if (pageHeight <= 0) return 0;
    int moved = 0;
    for (QTextBlock block = document.begin(); block.isValid(); block = block.next()) {
        if (block.blockFormat().headingLevel() == 0) continue;
        // Positions follow each page break already inserted above.
        const qreal top = document.documentLayout()->blockBoundingRect(block).top();
        const qreal onPage = top - std::floor(top / pageHeight) * pageHeight;
        if (onPage < pageHeight * kHeadingFoot) continue;
        QTextBlockFormat format;
        format.setPageBreakPolicy(QTextFormat::PageBreak_AlwaysBefore);
        QTextCursor(block).mergeBlockFormat(format);
        ++moved;
    }
    return moved;
}

void printWithPageNumbers(QTextDocument& document, QPagedPaintDevice& device,
                          const QString& pageText) {
    QPainter painter(&device);
    const qreal width = device.width();
    const qreal footer = painter.fontMetrics().height() * 2.5;
    const qreal pageHeight = device.height() - footer;
    document.setPageSize(QSizeF(width, pageHeight));
    keepHeadingsWithText(document);
    const int pages = document.pageCount();
    for (int page = 0; page < pages; ++page) {
        if (page > 0) device.newPage();
        const QRectF shown(0, page * pageHeight, width, pageHeight);
        painter.save();
        painter.translate(0, -shown.top());
        painter.setClipRect(shown);
        QAbstractTextDocumentLayout::PaintContext context;
        context.clip = shown;
        // Paper is white whatever the screen's theme: the layout's default
        // palette is the application's, whose text is light grey in dark
        // mode (the report came out nearly blank).
        context.palette.setColor(QPalette::Text, Qt::black);
        context.palette.setColor(QPalette::WindowText, Qt::black);
        context.palette.setColor(QPalette::Link, Qt::blue);
        document.documentLayout()->draw(&painter, context);
        painter.restore();
        painter.drawText(QRectF(0, pageHeight, width, footer), Qt::AlignCenter,
                         pageText.arg(page + 1).arg(pages));
    }
}

Status writeReportPdf(const QString& path, QTextDocument& document, const QString& title,
                      const QString& pageText) {
    // QPdfWriter writes straight into its target: render into a QSaveFile.
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return Error::invalidData(QCoreApplication::translate("cambench::CommissioningReport",
                                                              "Cannot write the report to %1: %2")
                                      .arg(path, file.errorString()));
    {
        QPdfWriter writer(&file);
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setTitle(title);
        writer.setCreator(QStringLiteral("CamBench"));
        writer.setResolution(150);
        printWithPageNumbers(document, writer, pageText);
    }
    if (!file.commit())
        return Error::invalidData(QCoreApplication::translate("cambench::CommissioningReport",
                                                              "Cannot write the report to %1: %2")
                                      .arg(path, file.errorString()));
    return success();
}

}  // namespace cambench
