#pragma once

#include "protocol_registry.h"

#include "model/result.h"

#include <QList>
#include <QPair>
#include <QString>
#include <QStringList>

#include <memory>

namespace cambench::comm {

// The one reader of the options protocols declare (ProtocolInfo::options):
// the command line, a machine file and the connection page all go through
// these functions, so none of them names an option of a family.

// Options as given, by name, with their text as typed: {"device", "5"}.
using OptionValues = QList<QPair<QString, QString>>;

// How a message names option `name` where it was given: "--device" on a
// command line, "\"device\"" in a machine file.
using OptionNaming = QString (*)(const QString& name);
QString commandLineOption(const QString& name);
QString fileKey(const QString& name);

// Every option name (and alias) any registered protocol declares, each once,
// in registration order.
QStringList protocolOptionNames();

// The declaration of `name` in `protocol`, or null when it has none.
const ProtocolOption* declaredOption(const ProtocolInfo& protocol, const QString& name);

// The families whose protocols take `name` with `value` (a choice only
// where it is one of its words): an option only one family's protocols
// take names that family on a command line.
QStringList familiesTaking(const QString& name, const QString& value);

// The protocol of `familyId` for `values` when no protocol is named:
// `preferred` when it takes them all, else the family's first that does
// (an "address" asks for a bus whose devices have addresses). A usage error
// naming the option no protocol of the family takes.
Result<const ProtocolInfo*> protocolTaking(const QString& familyId, const QString& preferred,
                                           const OptionValues& values, OptionNaming naming);

// Checks each of `values` against `protocol`'s declaration: a whole number
// in its range, a word among its choices. An option the protocol does not
// take is refused, naming the protocols of its family that do.
Status checkOptionValues(const ProtocolInfo& protocol, const OptionValues& values,
                         OptionNaming naming);

// New settings of `protocol` with `values` in them (checked before with
// checkOptionValues; those it does not take are left out) and the
// per-attempt timeout (0: derived from the line).
std::unique_ptr<ProtocolSettings> settingsWith(const ProtocolInfo& protocol,
                                               const OptionValues& values, int timeoutMs = 0);

// What `settings` hold of `protocol`'s options, as a machine file writes
// them: those that differ from their default, and those always written.
OptionValues optionValuesOf(const ProtocolInfo& protocol, const ProtocolSettings& settings);

}  // namespace cambench::comm
