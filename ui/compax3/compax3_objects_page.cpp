#include "compax3_objects_page.h"

#include "compax3_gui.h"
#include "compax3_object_model.h"

#include "comm/compax3/compax3_syntax.h"
#include "comm/compax3/usecases/compax3_parameters.h"
#include "comm/compax3/usecases/compax3_read_objects.h"
#include "ui/device_session.h"
#include "ui/report_dialog.h"
#include "ui/sentence.h"

#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSortFilterProxyModel>
#include <QTreeView>
#include <QVBoxLayout>

namespace cambench {

Compax3ObjectsPage::Compax3ObjectsPage(DeviceSession* session, Compax3Gui* gui, QWidget* parent)
    : Compax3Page(session, parent),
      m_gui(gui),
      m_model(gui->objects()),
      m_filter(new QSortFilterProxyModel(this)),
      m_tree(new QTreeView),
      m_search(new QLineEdit),
      m_rawObject(new QLineEdit),
      m_rawValue(new QLineEdit),
      m_write(new QPushButton(tr("Write changes…"))) {
    setObjectName(QStringLiteral("compax3ObjectsPage"));
    // A window built again (another language) shows the same typed values.
    m_model->retranslate();
    m_filter->setSourceModel(m_model);
    m_filter->setRecursiveFilteringEnabled(true);
    m_filter->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_filter->setFilterKeyColumn(-1);
    m_tree->setObjectName(QStringLiteral("compax3ObjectTree"));
    m_tree->setModel(m_filter);
    m_tree->setAlternatingRowColors(true);
    m_tree->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                            QAbstractItemView::AnyKeyPressed);
    m_tree->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_tree->expandToDepth(0);
    m_search->setObjectName(QStringLiteral("compax3Search"));
    m_search->setPlaceholderText(tr("Search objects (number, name, group)…"));
    m_search->setClearButtonEnabled(true);
    connect(m_search, &QLineEdit::textChanged, this, [this](const QString& text) {
        m_filter->setFilterFixedString(text);
        if (!text.isEmpty()) m_tree->expandAll();
    });
    connect(m_model, &Compax3ObjectModel::editRefused, this,
            [this](const QString& message) { showResult(asSentence(message), false); });
    connect(m_model, &Compax3ObjectModel::editAccepted, this, [this] {
        showResult(tr("%n value(s) typed in, not on the drive yet: Write changes sends them.",
                      nullptr, int(m_model->edits().size())),
                   true);
    });
    connect(gui, &Compax3Gui::dictionaryChanged, this, [this] {
        m_tree->expandToDepth(0);
        if (const QStringList problems = m_model->editProblems(); !problems.isEmpty())
            showResult(tr("The loaded dictionary refuses %n typed value(s); they stay typed in "
                          "and are not written until corrected: %1",
                          nullptr, int(problems.size()))
                           .arg(problems.join(QStringLiteral("; "))),
                       false);
    });

    auto* read = new QPushButton(tr("Read all"));
    read->setObjectName(QStringLiteral("compax3ReadAll"));
    connect(read, &QPushButton::clicked, this, &Compax3ObjectsPage::readAll);
    m_write->setObjectName(QStringLiteral("compax3WriteChanges"));
    connect(m_write, &QPushButton::clicked, this, &Compax3ObjectsPage::writeChanges);
    auto* discard = new QPushButton(tr("Discard changes"));
    connect(discard, &QPushButton::clicked, this, [this] {
        if (m_model->edits().isEmpty()) return;
        if (confirm(tr("Discard"), tr("Discard %n value(s) typed in but not written?", nullptr,
                                      int(m_model->edits().size()))))
            m_model->clearEdits();
    });
    auto* load = new QPushButton(tr("Load dictionary…"));
    connect(load, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Load object dictionary"), {},
                                                          tr("Compax3 dictionaries (*.json)"));
        if (!path.isEmpty()) loadDictionary(path);
    });
    auto* top = new QHBoxLayout;
    top->addWidget(m_search, 1);
    top->addWidget(read);
    top->addWidget(m_write);
    top->addWidget(discard);
    top->addWidget(load);

    m_rawObject->setObjectName(QStringLiteral("compax3RawObject"));
    m_rawObject->setPlaceholderText(tr("Object, e.g. O 1234,5"));
    m_rawObject->setMinimumWidth(180);
    m_rawValue->setObjectName(QStringLiteral("compax3RawValue"));
    m_rawValue->setPlaceholderText(tr("Value"));
    auto* rawRead = new QPushButton(tr("Read"));
    rawRead->setObjectName(QStringLiteral("compax3RawRead"));
    connect(rawRead, &QPushButton::clicked, this, [this] { readRaw(m_rawObject->text()); });
    auto* rawWrite = new QPushButton(tr("Write…"));
    rawWrite->setObjectName(QStringLiteral("compax3RawWrite"));
    connect(rawWrite, &QPushButton::clicked, this,
            [this] { writeRaw(m_rawObject->text(), m_rawValue->text()); });
    auto* raw = new QHBoxLayout;
    raw->addWidget(new QLabel(tr("Any object by number:")));
    raw->addWidget(m_rawObject);
    raw->addWidget(rawRead);
    raw->addWidget(m_rawValue);
    raw->addWidget(rawWrite);
    raw->addStretch(1);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_tree, 1);
    layout->addLayout(raw);
    layout->addWidget(resultLine());
}

void Compax3ObjectsPage::factsChanged() {
    if (facts().known) readAll();
}

void Compax3ObjectsPage::markStale() {
    m_model->markStale();
}

void Compax3ObjectsPage::readAll() {
    read(m_model->readableObjects());
}

void Compax3ObjectsPage::read(const QList<Compax3ObjectId>& ids) {
    if (!facts().known) return;
    using usecases::Compax3Reading;
    session()->run<comm::Compax3Device, QList<Compax3Reading>>(
        this, tr("Read objects"),
        [ids](comm::Compax3Device& device, comm::JobContext& job) {
            return usecases::readCompax3Objects(device, ids, false,
                                                usecases::UseCaseProgress::of(job));
        },
        [this](Result<QList<Compax3Reading>> values) {
            if (!values) {
                showResult(tr("Not read: %1").arg(asSentence(values.error().message)), false);
                return;
            }
            const QDateTime now = QDateTime::currentDateTime();
            int refused = 0;
            int absent = 0;
            // The columns fit their contents once, after all values: fitted
            // after each of ~200 values, the window stood still for seconds.
            QHeaderView* header = m_tree->header();
            header->setSectionResizeMode(QHeaderView::Interactive);
            for (const Compax3Reading& value : *values) {
                if (!value.refused()) {
                    m_model->setDriveValue(value.id, value.value, now);
                } else if (comm::compax3RefusalMeansAbsent(value.refusal,
                                                           m_gui->dictionary().refusals())) {
                    m_model->setDriveAbsent(value.id, value.refusal.message);
                    ++absent;
                } else {
                    m_model->setDriveError(value.id, value.refusal.message);
                    ++refused;
                }
            }
            header->setSectionResizeMode(QHeaderView::ResizeToContents);
            QString text =
                refused == 0 ? tr("Read %n object(s) at %1.", nullptr, int(values->size()) - absent)
                                   .arg(now.toString(QStringLiteral("HH:mm:ss")))
                             : tr("Read %1 objects; the drive refused %2 (hover over "
                                  "\"refused\" for its answer).")
                                   .arg(values->size() - refused - absent)
                                   .arg(refused);
            if (absent > 0)
                text += QLatin1Char(' ') +
                        tr("%n object(s) are not on this drive (greyed).", nullptr, absent);
            showResult(text, refused == 0);
        });
}

void Compax3ObjectsPage::writeChanges() {
    const QHash<Compax3ObjectId, Compax3ObjectModel::Edit>& edits = m_model->edits();
    if (edits.isEmpty()) {
        showResult(tr("Nothing to write: no value is typed in."), true);
        return;
    }
    if (!facts().known) {
        showResult(tr("Not connected to a drive: the values stay typed in."), false);
        return;
    }
    // Checked again against the dictionary in use before the first byte.
    if (const QStringList problems = m_model->editProblems(); !problems.isEmpty()) {
        showResult(tr("Nothing was written: the dictionary in use refuses %n typed value(s) "
                      "(they stay typed in; correct or clear them): %1",
                      nullptr, int(problems.size()))
                       .arg(problems.join(QStringLiteral("; "))),
                   false);
        return;
    }
    QList<usecases::Compax3Write> writes;
    QStringList lines;
    QList<Compax3ObjectId> ids = edits.keys();
    std::sort(ids.begin(), ids.end());
    for (const Compax3ObjectId& id : ids) {
        const Compax3ObjectModel::Edit& edit = edits.value(id);
        writes << usecases::Compax3Write{id, edit.value, edit.wire};
        lines << tr("%1: %2 → %3")
                     .arg(id.text(), m_model->driveValue(id).value_or(tr("(not read)")),
                          edit.value);
    }
    if (!confirm(tr("Write"),
                 tr("Write %n value(s) to the drive %1?", nullptr, int(writes.size()))
                     .arg(facts().identity.serial),
                 lines.join(QLatin1Char('\n'))))
        return;
    const Compax3Dictionary dictionary = m_model->dictionary();
    session()->run<comm::Compax3Device, usecases::OutcomeTally>(
        this, tr("Write objects"),
        [writes, dictionary](comm::Compax3Device& device, comm::JobContext& job) {
            return Result<usecases::OutcomeTally>(usecases::writeCompax3Objects(
                device, writes, dictionary, usecases::Compax3WriteSource::Typed,
                usecases::UseCaseProgress::of(job)));
        },
        [this, writes](Result<usecases::OutcomeTally> tally) {
            if (!tally) {
                showResult(tr("Not written: %1").arg(asSentence(tally.error().message)), false);
                return;
            }
            // Written or unchanged: on the drive now. Anything else stays
            // typed in, so that nothing is lost.
            for (int i = 0; i < writes.size() && i < tally->lines().size(); ++i) {
                const usecases::WriteState state = tally->lines().at(i).state;
                if (state == usecases::WriteState::Written ||
                    state == usecases::WriteState::Unchanged) {
                    m_model->setDriveValue(writes.at(i).id, writes.at(i).value,
                                           QDateTime::currentDateTime());
                    m_model->clearEdit(writes.at(i).id);
                }
            }
            showResult(tally->summary(), tally->complete());
            if (!tally->complete()) {
                // What the drive holds now is read again: a failed write
                // may have changed it, and the page must not show the old
                // value as the drive's.
                QList<Compax3ObjectId> touched;
                for (const usecases::Compax3Write& write : writes) touched << write.id;
                read(touched);
                ReportDialog::presentTally(window(), tr("Write"), *tally);
            }
        });
}

void Compax3ObjectsPage::readRaw(const QString& object) {
    const Result<Compax3ObjectId> id = parseCompax3Object(object);
    if (!id) {
        showResult(asSentence(id.error().message), false);
        return;
    }
    m_model->ensureObject(*id);
    m_tree->scrollTo(m_filter->mapFromSource(m_model->indexOf(*id, Compax3ObjectModel::Object)));
    read({*id});
}

void Compax3ObjectsPage::writeRaw(const QString& object, const QString& value) {
    const Result<Compax3ObjectId> id = parseCompax3Object(object);
    if (!id) {
        showResult(asSentence(id.error().message), false);
        return;
    }
    if (*id == comm::kCompax3ControlWord) {
        showResult(tr("1100.3 is the control word, which moves the axis: use the Motion page."),
                   false);
        return;
    }
    m_model->ensureObject(*id);
    if (const Status set = m_model->setEdit(*id, value); !set) {
        showResult(asSentence(set.error().message), false);
        return;
    }
    writeChanges();
}

void Compax3ObjectsPage::loadDictionary(const QString& path) {
    const Result<Compax3Dictionary> loaded = Compax3Dictionary::load(path);
    if (!loaded) {
        ReportDialog::present(
            window(), QMessageBox::Warning, tr("Load dictionary"),
            tr("The dictionary was not loaded: %1").arg(asSentence(loaded.error().message)));
        return;
    }
    if (!m_model->edits().isEmpty() &&
        !confirm(tr("Load"),
                 tr("%n value(s) are typed in but not written. Load the dictionary anyway? "
                    "Values of objects it still lists stay typed in.",
                    nullptr, int(m_model->edits().size()))))
        return;
    m_gui->setDictionary(*loaded);
    // The typed values it refuses were said when it was set.
    if (m_model->editProblems().isEmpty())
        showResult(
            tr("Loaded %n object(s) from %1.", nullptr, int(loaded->objects().size())).arg(path),
            true);
    readAll();
}

}  // namespace cambench
