#pragma once

#include <QByteArray>
#include <QHash>
#include <QList>
#include <QVariant>

namespace cambench::comm {

// The decoded (or to-be-encoded) fields of one request or reply, by the
// field names of the command catalogue. Numbers are qint64 (signed fields
// already sign-extended), texts and binary data are QByteArray (texts
// without their NUL padding), word arrays are QList<qint64>.
class Fields {
public:
    Fields() = default;
    Fields(std::initializer_list<std::pair<const char*, QVariant>> init) {
        for (const auto& [name, value] : init) m_values.insert(QByteArray(name), value);
    }

    Fields& set(const QByteArray& name, qint64 value) {
        m_values.insert(name, QVariant::fromValue(value));
        return *this;
    }
    Fields& setBytes(const QByteArray& name, const QByteArray& value) {
        m_values.insert(name, QVariant(value));
        return *this;
    }
    Fields& setWords(const QByteArray& name, const QList<qint64>& words) {
        m_values.insert(name, QVariant::fromValue(words));
        return *this;
    }

    bool has(const QByteArray& name) const { return m_values.contains(name); }
    qint64 num(const QByteArray& name) const { return m_values.value(name).toLongLong(); }
    QByteArray bytes(const QByteArray& name) const { return m_values.value(name).toByteArray(); }
    QList<qint64> words(const QByteArray& name) const {
        return m_values.value(name).value<QList<qint64>>();
    }
    QVariant value(const QByteArray& name) const { return m_values.value(name); }
    QList<QByteArray> names() const { return m_values.keys(); }
    bool isEmpty() const { return m_values.isEmpty(); }

    friend bool operator==(const Fields& a, const Fields& b) { return a.m_values == b.m_values; }

private:
    QHash<QByteArray, QVariant> m_values;
};

}  // namespace cambench::comm
