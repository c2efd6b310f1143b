#pragma once

#include <QByteArray>

namespace cambench {

// The bytes of model/compax3/compax3-objects.json, built into the program
// (compax3_builtin_objects.cpp is generated from it by CMake).
QByteArray compax3BuiltinObjectsJson();

}  // namespace cambench
