#pragma once

#include "compax3_page.h"

class QLineEdit;
class QPushButton;
class QSortFilterProxyModel;
class QTreeView;

namespace cambench {

class Compax3Gui;
class Compax3ObjectModel;

// Objects: the dictionary as a tree by group with a search, each object's
// value on the drive (read when it was, grey when stale) and the value
// typed in (checked against range and type at once, marked until written).
// "Write changes" asks first, then reports every object written, unchanged
// or failed; what failed stays typed in. Any object by number below, also
// one the dictionary lacks.
class Compax3ObjectsPage : public Compax3Page {
    Q_OBJECT
public:
    Compax3ObjectsPage(DeviceSession* session, Compax3Gui* gui, QWidget* parent = nullptr);

    QString sectionTitle() const override { return tr("Objects"); }
    void markStale() override;
    Compax3ObjectModel* model() const { return m_model; }
    QTreeView* tree() const { return m_tree; }

    // Reads every readable object of the tree.
    void readAll();
    // Reads these objects again (another page wrote them): the drive's
    // values replace what was shown; what is typed stays typed.
    void read(const QList<Compax3ObjectId>& ids);
    void writeChanges();
    // The raw entry: "O 1234,5" or "1234.5".
    void readRaw(const QString& object);
    void writeRaw(const QString& object, const QString& value);
    void loadDictionary(const QString& path);

protected:
    void factsChanged() override;

private:
    Compax3Gui* m_gui;
    Compax3ObjectModel* m_model;
    QSortFilterProxyModel* m_filter;
    QTreeView* m_tree;
    QLineEdit* m_search;
    QLineEdit* m_rawObject;
    QLineEdit* m_rawValue;
    QPushButton* m_write;
};

}  // namespace cambench
