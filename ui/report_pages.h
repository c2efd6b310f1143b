#pragma once

#include "model/result.h"

#include <QList>
#include <QString>
#include <QStringList>

class QDateTime;
class QPagedPaintDevice;
class QTextDocument;

namespace cambench {

// A time as every printed report writes it, in every language the same:
// "2025-11-29 14:03" (local time) - one format on a page.
QString reportTime(const QDateTime& time);

// HTML pieces of a report's section, the texts escaped: a paragraph, a
// heading below the section's own, a bordered table (its head row first,
// none when `head` is empty).
QString reportParagraph(const QString& text);
QString reportHeading(const QString& text);
QString reportTable(const QStringList& head, const QList<QStringList>& rows);

// Pages of a printed report. A heading in the last part of a page starts
// the next one instead, so that it never stands alone at a page's foot;
// returns how many were moved. The document's page size must be set.
int keepHeadingsWithText(QTextDocument& document);

// Prints `document` onto `device` page by page with "Page 1 of 3" at the
// foot of each page (QTextDocument::print numbers nothing). `pageText` is
// the translated "Page %1 of %2".
void printWithPageNumbers(QTextDocument& document, QPagedPaintDevice& device,
                          const QString& pageText);

// Writes `document` as an A4 PDF titled `title` to `path`, page-numbered
// with `pageText`, or leaves `path` untouched; the error names the file.
Status writeReportPdf(const QString& path, QTextDocument& document, const QString& title,
                      const QString& pageText);

}  // namespace cambench
