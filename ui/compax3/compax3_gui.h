#pragma once

#include "ui/family_gui.h"

#include "model/compax3/compax3_dictionary.h"

namespace cambench {

// The Compax3 family's part of the GUI for the whole run: the object
// dictionary in use (the shipped one or the user's) and the watch list,
// kept across a window rebuilt on a language switch.
class Compax3Gui : public FamilyGui {
    Q_OBJECT
public:
    Compax3Gui(DeviceSession* session, QObject* parent = nullptr);

    const Compax3Dictionary& dictionary() const { return m_dictionary; }
    void setDictionary(const Compax3Dictionary& dictionary);
    QList<Compax3ObjectId>& watchList() { return m_watch; }

    FamilyWindow* createWindow(MainWindow* window) override;
    QString windowSubject() const override { return identityLine(); }

Q_SIGNALS:
    void dictionaryChanged();

private:
    Compax3Dictionary m_dictionary;
    QList<Compax3ObjectId> m_watch;
};

}  // namespace cambench
