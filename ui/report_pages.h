#pragma once

#include <QString>

class QPagedPaintDevice;
class QTextDocument;

namespace cambench {

// Pages of a printed report. A heading in the last part of a page starts
// the next one instead, so that it never stands alone at a page's foot;
// returns how many were moved. The document's page size must be set.
int keepHeadingsWithText(QTextDocument& document);

// Prints `document` onto `device` page by page with "Page 1 of 3" at the
// foot of each page (QTextDocument::print numbers nothing). `pageText` is
// the translated "Page %1 of %2".
void printWithPageNumbers(QTextDocument& document, QPagedPaintDevice& device,
                          const QString& pageText);

}  // namespace cambench
