#include "mc1_parameters.h"

#include "model/file_read.h"

#include <QCoreApplication>

namespace cambench::comm {

namespace {

constexpr Mc1AxisValue kValues[] = {Mc1AxisValue::Position, Mc1AxisValue::Target,
                                    Mc1AxisValue::Status};

Mc1AxisParameterTable tableFrom(quint16 base) {
    Mc1AxisParameterTable table;
    for (int axis = kMc1FirstAxis; axis <= kMc1LastAxis; ++axis)
        for (int i = 0; i < 3; ++i)
            table.numbers.insert({axis, kValues[i]}, quint16(base + 0x10 * axis + i));
    return table;
}

Error lineError(int line, const QString& what) {
    return Error::invalidData(
        QCoreApplication::translate("cambench::comm", "line %1: %2").arg(line).arg(what));
}

}  // namespace

Mc1VariableRange mc1VariableRange(Mc1Variant) {
    return {};
}

QString mc1AxisValueName(Mc1AxisValue value) {
    switch (value) {
        case Mc1AxisValue::Position:
            return QStringLiteral("position");
        case Mc1AxisValue::Target:
            return QStringLiteral("target");
        case Mc1AxisValue::Status:
            return QStringLiteral("status");
    }
    return {};
}

std::optional<quint16> Mc1AxisParameterTable::number(int axis, Mc1AxisValue value) const {
    const auto it = numbers.find({axis, value});
    if (it == numbers.end()) return std::nullopt;
    return *it;
}

Mc1AxisParameterTable mc1ProvisionalAxisParameters() {
    Mc1AxisParameterTable table = tableFrom(0x1000);
    table.source = QCoreApplication::translate(
        "cambench::comm", "CamBench's built-in guess (comm/mc1/README.md), not the controller's");
    table.provisional = true;
    return table;
}

Mc1AxisParameterTable mc1AxisParametersFrom(quint16 base, const QString& source) {
    Mc1AxisParameterTable table = tableFrom(base);
    table.source = source;
    table.provisional = false;
    return table;
}

Result<Mc1AxisParameterTable> parseMc1AxisParameterTable(const QByteArray& text,
                                                         const QString& source) {
    Mc1AxisParameterTable table;
    table.source = source;
    table.provisional = false;
    const QList<QByteArray> lines = text.split('\n');
    for (int index = 0; index < lines.size(); ++index) {
        const int lineNumber = index + 1;
        const QString line = QString::fromUtf8(lines.at(index)).trimmed();
        if (line.isEmpty() || line.startsWith(QLatin1Char('#'))) continue;
        const QStringList fields = line.split(QLatin1Char(','));
        if (table.numbers.isEmpty() && fields.size() == 3 &&
            fields.at(0).trimmed() == QLatin1String("name"))
            continue;  // the header
        if (fields.size() != 3)
            return lineError(lineNumber, QCoreApplication::translate(
                                             "cambench::comm",
                                             "expected name,axis,parameter (3 fields), found %1")
                                             .arg(fields.size()));
        const QString name = fields.at(0).trimmed().toLower();
        std::optional<Mc1AxisValue> value;
        for (Mc1AxisValue candidate : kValues)
            if (name == mc1AxisValueName(candidate)) value = candidate;
        if (!value)
            return lineError(
                lineNumber,
                QCoreApplication::translate(
                    "cambench::comm", "the name must be position, target or status, not \"%1\"")
                    .arg(fields.at(0).trimmed()));
        bool ok = false;
        const int axis = fields.at(1).trimmed().toInt(&ok);
        if (!ok || axis < kMc1FirstAxis || axis > kMc1LastAxis)
            return lineError(lineNumber,
                             QCoreApplication::translate("cambench::comm",
                                                         "the axis must be %1 to %2, not \"%3\"")
                                 .arg(kMc1FirstAxis)
                                 .arg(kMc1LastAxis)
                                 .arg(fields.at(1).trimmed()));
        const QString numberText = fields.at(2).trimmed();
        const uint number = numberText.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)
                                ? numberText.mid(2).toUInt(&ok, 16)
                                : numberText.toUInt(&ok, 10);
        if (!ok || number > 0xFFFF)
            return lineError(lineNumber,
                             QCoreApplication::translate(
                                 "cambench::comm",
                                 "the parameter must be 0 to 65535 (or 0x0000 to 0xFFFF), not "
                                 "\"%1\"")
                                 .arg(numberText));
        if (table.numbers.contains({axis, *value}))
            return lineError(lineNumber,
                             QCoreApplication::translate("cambench::comm",
                                                         "the %1 of axis %2 is named a second time")
                                 .arg(mc1AxisValueName(*value))
                                 .arg(axis));
        table.numbers.insert({axis, *value}, quint16(number));
    }
    if (table.numbers.isEmpty())
        return Error::invalidData(QCoreApplication::translate(
            "cambench::comm", "no name,axis,parameter line: the file holds no parameter"));
    return table;
}

Result<Mc1AxisParameterTable> loadMc1AxisParameterTable(const QString& path) {
    const Result<QByteArray> bytes = readFileBytes(path);
    if (!bytes) return bytes.error();
    return parseMc1AxisParameterTable(*bytes, path);
}

}  // namespace cambench::comm
