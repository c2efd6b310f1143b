#pragma once

#include <QList>

namespace cambench::comm {

// Where a model setting key (model/system_settings.h) lives on the device:
// a field of a command's reply, written back by the '!' command of the same
// name with the same fields.
struct SettingField {
    const char* key;    // model key, e.g. "actualValueHysteresis"
    const char* field;  // catalogue field, e.g. "value"
};

// One command that reads (and, if the catalogue has its '!' form, writes)
// one or more settings at once.
struct SettingPage {
    const char* command;
    QList<SettingField> fields;
    // >= 0: a special-encoder parameter page (notes 3). Its '!' form also
    // carries the two text lines and this type, and writing it selects the
    // programmable special encoder.
    int encoderType = -1;
};

// Every setting of settingSpecs(), one line each (composite pages: one line
// per page).
const QList<SettingPage>& settingPages();

// The text lines a special-encoder page is written with.
constexpr const char* kEncoderText1Key = "specialEncoder.text1";
constexpr const char* kEncoderText2Key = "specialEncoder.text2";
constexpr const char* kEncoderTypeKey = "specialEncoder.type";

}  // namespace cambench::comm
