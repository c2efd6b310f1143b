#pragma once

#include "model/camcon/carry_over.h"

#include <QList>
#include <QMap>

#include <functional>
#include <optional>
#include <utility>

namespace cambench {

// Where values that replace the workspace's come from. A device read also
// replaces the device copy; a file (a project) only the edited state.
enum class ValueSource { Device, File };

// One section of a device's data as the PC holds it: the device's copy
// (last read from or written to it) and, for each item the person or a
// project wants otherwise, the edit. What is shown is the edit, else the
// device's value. An edit equal to the device's value is no edit, so
// "changed" is exactly "differs from the device, or the device's value is
// not known". Pure data: whoever owns it learns of every change through
// onChange (the workspace turns it into its signals).
template <class Key, class Value>
class SectionCopies {
public:
    using Map = QMap<Key, Value>;

    // Called after every change (not after a call that changed nothing).
    std::function<void()> onChange;

    // As shown: the edit, else the device's; nullopt when neither is known.
    std::optional<Value> value(const Key& key) const {
        if (const auto edit = m_edits.constFind(key); edit != m_edits.cend()) return *edit;
        return deviceValue(key);
    }
    std::optional<Value> deviceValue(const Key& key) const {
        if (const auto device = m_device.constFind(key); device != m_device.cend()) return *device;
        return std::nullopt;
    }
    // Every item known, as shown (what a project saved now holds).
    Map shown() const {
        Map all = m_device;
        for (auto it = m_edits.cbegin(); it != m_edits.cend(); ++it) all.insert(it.key(), *it);
        return all;
    }
    const Map& device() const { return m_device; }
    // Whether the device's whole section was read (merge from the device)
    // since the last forgetDevice(): a write of single items does not make it so.
    bool known() const { return m_known; }

    bool isChanged(const Key& key) const { return m_edits.contains(key); }
    QList<Key> changedKeys() const { return m_edits.keys(); }
    int changedCount() const { return int(m_edits.size()); }

    // The person (or a caller on their behalf) wants `value` for `key`.
    void edit(const Key& key, const Value& value) {
        if (putEdit(key, value)) notify();
    }
    // The device holds `value` for `key` now (after a write, or a read of
    // this one item); an edit that equals it is done.
    void setDevice(const Key& key, const Value& value) {
        if (putDevice(key, value)) notify();
    }
    // Values that arrive for the items they name; the one rule: with
    // `keepEdits` an edited item keeps its edit (a device's value still
    // becomes its device copy), every other item takes the new value. Items
    // not named stay as they are.
    void merge(const Map& values, ValueSource source, bool keepEdits) {
        if (putAll(values, source, keepEdits)) notify();
    }
    // The device's whole section: what it no longer names is no longer on
    // it (an edit of such an item stays, counted as not on the device); then
    // merge() with its one rule.
    void mergeWhole(const Map& values, bool keepEdits) {
        m_device.clear();
        m_known = false;
        putAll(values, ValueSource::Device, keepEdits);
        notify();
    }
    // Another device answered (or the connected one lacks this section): the
    // device copy is forgotten; of what was shown, what `carry` says stays,
    // as edits (for the new device they are not on it).
    void forgetDevice(CarryOver carry) {
        if (carry == CarryOver::Nothing) m_edits.clear();
        if (carry == CarryOver::Everything) m_edits = shown();
        m_device.clear();
        m_known = false;
        notify();
    }
    // The item shows the device's value again.
    void dropEdit(const Key& key) {
        if (m_edits.remove(key) > 0) notify();
    }
    // Forgets edits and device copy (a new project).
    void clear() {
        m_edits.clear();
        m_device.clear();
        m_known = false;
        notify();
    }

private:
    // The rules of edit() and setDevice(), without telling anyone; true when
    // something changed.
    bool putEdit(const Key& key, const Value& value) {
        const auto device = m_device.constFind(key);
        if (device != m_device.cend() && *device == value) return m_edits.remove(key) > 0;
        const auto edit = m_edits.constFind(key);
        if (edit != m_edits.cend() && *edit == value) return false;
        m_edits.insert(key, value);
        return true;
    }
    bool putDevice(const Key& key, const Value& value) {
        const auto device = m_device.constFind(key);
        const bool same = device != m_device.cend() && *device == value;
        m_device.insert(key, value);
        const auto edit = m_edits.constFind(key);
        if (edit != m_edits.cend() && *edit == value) {
            m_edits.remove(key);
            return true;
        }
        return !same;
    }
    bool putAll(const Map& values, ValueSource source, bool keepEdits) {
        bool any = source == ValueSource::Device && !m_known;
        if (source == ValueSource::Device) m_known = true;
        for (auto it = values.cbegin(); it != values.cend(); ++it) {
            const bool keep = keepEdits && isChanged(it.key());
            if (source == ValueSource::Device) {
                any |= putDevice(it.key(), *it);
                if (!keep) any |= m_edits.remove(it.key()) > 0;
            } else if (!keep) {
                any |= putEdit(it.key(), *it);
            }
        }
        return any;
    }
    void notify() const {
        if (onChange) onChange();
    }

    Map m_device;
    Map m_edits;
    bool m_known = false;
};

// A section that is one value (the programming program, the EEPROM lock):
// the same copies under a single key.
template <class Value>
class SingleCopy : public SectionCopies<int, Value> {
    using Base = SectionCopies<int, Value>;

public:
    std::optional<Value> value() const { return Base::value(0); }
    std::optional<Value> deviceValue() const { return Base::deviceValue(0); }
    bool isChanged() const { return Base::isChanged(0); }
    void edit(const Value& value) { Base::edit(0, value); }
    void setDevice(const Value& value) { Base::setDevice(0, value); }
    void dropEdit() { Base::dropEdit(0); }
    // A value that arrives (nullopt: none), by merge()'s one rule.
    void merge(const std::optional<Value>& value, ValueSource source, bool keepEdits) {
        if (value) Base::merge({{0, *value}}, source, keepEdits);
    }
};

}  // namespace cambench
