#pragma once

#include "model/camcon/device_info.h"
#include "model/camcon/user.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QList>
#include <QPair>
#include <QString>
#include <QVariant>

namespace cambench::cli {

// The fields of `info`, in print order, with stable keys for text and JSON.
QList<QPair<QString, QVariant>> deviceInfoEntries(const DeviceInfo& info);
QJsonObject deviceInfoJson(const DeviceInfo& info);

// "program selection, programming" for a user's rights mask.
QString rightsText(quint32 rights);

// Device bytes for a terminal: printable ASCII as is, others as \xHH.
QString printableBytes(const QByteArray& bytes);

// The numbers (from 1) of the bits that are set: outputs or inputs on.
QList<int> onNumbers(const QList<bool>& bits);
// "1,3,7", or "none".
QString numberList(const QList<int>& numbers);
QJsonArray jsonNumbers(const QList<int>& numbers);

// "key: value" lines.
QString keyValueLines(const QList<QPair<QString, QVariant>>& entries);

}  // namespace cambench::cli
