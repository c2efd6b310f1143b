#pragma once

#include "rk512.h"
#include "table_backend.h"

#include "comm/engine/request_engine.h"
#include "comm/transport/transport.h"

#include <QList>

namespace cambench::comm::table {

// How the PC talks to a CamCon's table interface: the RK512 variant and the
// link's patience. Line timing comes from the connection.
struct TableSettings {
    Rk512Variant variant = Rk512Variant::N96;
    int timeoutMs = 0;  // per attempt, waiting for the reply; 0 = derived from the line
    int retries = 3;    // further attempts after the first (each up to 6 3964R attempts)
};

// Speaks RK512 and the short commands over a TableBackend: table words in,
// table words out, split into telegrams of at most 128 data bytes. Every
// telegram is one engine request whose retry policy the caller states
// (reads are always idempotent). Lives in the worker thread.
class TableLink {
public:
    TableLink(Transport& transport, TableSettings settings, LineTiming line = {});

    const TableSettings& settings() const { return m_settings; }
    Rk512Variant variant() const { return m_settings.variant; }
    // Table words 0..reachableWords()-1 of an area can be addressed.
    int reachableWords() const;
    RequestEngine& engine() { return m_engine; }
    const TableBackend& backend() const { return m_backend; }
    // One 3964R attempt per telegram (Detect's probe; the engine's retries
    // are DeviceConnection::probe()'s).
    void setProbing();

    // `count` words from `firstWord` of `area`.
    Result<QList<qint32>> readWords(int area, int firstWord, int count);
    Result<qint32> readWord(int area, int word);
    // Writes `values` from `firstWord`, each telegram with `retry`. On a
    // failure `written` (when given) tells how many leading words the device
    // has taken.
    Status writeWords(int area, int firstWord, const QList<qint32>& values,
                      RetryPolicy retry = RetryPolicy::Idempotent, int* written = nullptr);
    Status writeWord(int area, int word, qint32 value, RetryPolicy retry = RetryPolicy::Idempotent);

    // A short command telegram (short_commands.h); returns the reply
    // telegram, which the caller decodes. `longestReplyBytes` bounds the
    // wait for it.
    Result<QByteArray> shortCommand(const QByteArray& telegram, const QString& label,
                                    int longestReplyBytes, RetryPolicy retry);

    int lastAttempts() const { return m_engine.lastAttempts(); }

private:
    Result<QByteArray> transfer(const Rk512Request& request, RetryPolicy retry);

    TableSettings m_settings;
    TableBackend m_backend;
    RequestEngine m_engine;
};

}  // namespace cambench::comm::table
