#pragma once

#include <QList>
#include <QString>
#include <QStringList>

#include <memory>

namespace cambench::comm {

// What every registry of CamBench (families, protocols, simulators) does
// with the things registered in it, found by an id member such as
// FamilyInfo::id: add (again: replaces), find, list in the order added.
// Entries never move, so pointers to them stay valid.
template <class Info, QString Info::*Id>
class IdRegistry {
public:
    void add(Info info) {
        for (auto& existing : m_entries) {
            if ((*existing).*Id == info.*Id) {
                *existing = std::move(info);  // registering again replaces
                return;
            }
        }
        m_entries.append(std::make_shared<Info>(std::move(info)));
    }
    // Ids compare without case: "Standard" on a command line finds "standard".
    const Info* find(const QString& id) const {
        for (const auto& entry : m_entries)
            if (((*entry).*Id).compare(id, Qt::CaseInsensitive) == 0) return entry.get();
        return nullptr;
    }
    QList<const Info*> all() const {
        QList<const Info*> list;
        for (const auto& entry : m_entries) list.append(entry.get());
        return list;
    }
    // "standard, multiuser, 3964r-n96" for usage messages.
    QString idList() const {
        QStringList ids;
        for (const auto& entry : m_entries) ids.append((*entry).*Id);
        return ids.join(QStringLiteral(", "));
    }

private:
    QList<std::shared_ptr<Info>> m_entries;
};

}  // namespace cambench::comm
