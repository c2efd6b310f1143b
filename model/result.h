#pragma once

#include <QCoreApplication>
#include <QString>

#include <optional>
#include <utility>

namespace cambench {

// What went wrong, in the categories a caller has to tell apart. The command
// line maps them to its exit codes (see app/cli/exit_codes.h).
enum class ErrorKind {
    None,
    DeviceError,    // the device answered ERR + number (manual 4.6.1)
    NotUnderstood,  // the device answered :Z (command unknown to this firmware)
    Communication,  // timeout, port gone, garbage after all retries
    InvalidData,    // a file or a value that fails validation
    Cancelled,      // the user cancelled
    Usage,          // a caller asked for something impossible (wrong arguments)
    // What was asked is not there on the connected device: its protocol or
    // variant lacks the command or the section, or the device is not the
    // variant named. Nothing was sent for it.
    Unsupported,
};

struct Error {
    ErrorKind kind = ErrorKind::None;
    QString message;        // complete sentence for a person: what, where, what to do
    qint32 deviceCode = 0;  // the device's error number for DeviceError, else 0

    static Error device(qint32 code, QString message) {
        return {ErrorKind::DeviceError, std::move(message), code};
    }
    static Error communication(QString message) {
        return {ErrorKind::Communication, std::move(message), 0};
    }
    static Error invalidData(QString message) {
        return {ErrorKind::InvalidData, std::move(message), 0};
    }
    static Error cancelled() {
        return {ErrorKind::Cancelled, QCoreApplication::translate("cambench::model", "Cancelled."),
                0};
    }
    static Error usage(QString message) { return {ErrorKind::Usage, std::move(message), 0}; }
    static Error unsupported(QString message) {
        return {ErrorKind::Unsupported, std::move(message), 0};
    }
};

// Value or error, never both. Modelled on ModbusScope's result.h: per-item
// results instead of exceptions, so a batch can report what failed and go on.
template <class T>
class Result {
public:
    Result(T value) : m_value(std::move(value)) {}      // NOLINT: implicit by design
    Result(Error error) : m_error(std::move(error)) {}  // NOLINT: implicit by design

    bool ok() const { return m_value.has_value(); }
    explicit operator bool() const { return ok(); }
    const T& value() const& { return *m_value; }
    T& value() & { return *m_value; }
    T&& value() && { return std::move(*m_value); }
    const T& operator*() const { return *m_value; }
    const T* operator->() const { return &*m_value; }
    const Error& error() const { return m_error; }

private:
    std::optional<T> m_value;
    Error m_error;
};

// For operations that return nothing but can fail.
struct Done {};
using Status = Result<Done>;
inline Status success() {
    return Done{};
}

}  // namespace cambench
