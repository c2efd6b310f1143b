#pragma once

#include "compax3_report.h"

#include "ui/family_gui.h"

#include "model/compax3/compax3_dictionary.h"

#include <optional>

namespace cambench {

class Compax3ObjectModel;

// The Compax3 family's part of the GUI for the whole run: the object
// dictionary in use (the shipped one or the user's), the objects with the
// values typed in and not written yet, and the watch list, kept across a
// window rebuilt on a language switch.
class Compax3Gui : public FamilyGui {
    Q_OBJECT
public:
    Compax3Gui(DeviceSession* session, QObject* parent = nullptr);

    const Compax3Dictionary& dictionary() const { return m_dictionary; }
    void setDictionary(const Compax3Dictionary& dictionary);
    QList<Compax3ObjectId>& watchList() { return m_watch; }
    // The Objects page's tree: the drive's values and the values typed in.
    Compax3ObjectModel* objects() const { return m_objects; }

    FamilyWindow* createWindow(MainWindow* window) override;
    QString windowSubject() const override { return identityLine(); }
    // Values typed in on the Objects page, not on the drive yet.
    int unwrittenCount() const override;
    void readForReport(QWidget* parent, std::function<void(const Status&)> done) override;
    QString reportSection(QTextDocument& document, const QString& resourcePrefix) const override;

Q_SIGNALS:
    void dictionaryChanged();

private:
    Compax3Dictionary m_dictionary;
    Compax3ObjectModel* m_objects;
    QList<Compax3ObjectId> m_watch;
    std::optional<Compax3ReportReading> m_report;  // the last reading for a report
};

}  // namespace cambench
