#pragma once

#include "model/camcon/cam_program.h"
#include "model/camcon/cam_validation.h"

#include <QAbstractTableModel>

namespace cambench {

class CamDocument;

// The cams of one track: switch-on, switch-off and length, editable through
// the document's undo stack. A cell in error is red and its tooltip says why.
class CamTableModel : public QAbstractTableModel {
    Q_OBJECT

public:
    enum Column { OnColumn, OffColumn, LengthColumn, COUNT };

    explicit CamTableModel(CamDocument* document, QObject* parent = nullptr);

    void setTrack(int program, int output);
    int program() const { return m_program; }
    int output() const { return m_output; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

private:
    void reload();
    const CamProblem* problemAt(int row) const;
    QVariant valueData(const Cam& cam, int column, int role) const;

    CamDocument* m_document;
    int m_program = 0;
    int m_output = 1;
    // A copy of the track, so row counts stay consistent until the model
    // has announced a change.
    QList<Cam> m_cams;
    QList<CamProblem> m_problems;
};

}  // namespace cambench
