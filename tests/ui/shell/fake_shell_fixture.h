#pragma once

// What the shell's tests on the test-only fake family share
// (tests/family/fake_family.h): the setup of a test process and a start on
// a simulated fake device.
#include "../../family/fake_family.h"
#include "shell_fixture.h"

#include "ui/language.h"

namespace cambench::test {

// Settings of the test's own, the English catalogue, the fake family
// registered beside the built-in ones. Call in initTestCase().
inline bool setUpWithTheFakeFamily() {
    useTestSettings();
    fake::registerFakeFamily();
    return setLanguage(QStringLiteral("en"));
}

// A shell connected to a simulated fake device; its port says how many
// axes it has ("sim:throttle=0,axes=2").
inline std::unique_ptr<Shell> startOnFake(const QString& port = QStringLiteral("sim:throttle=0")) {
    return startOnSimulator(port, QStringLiteral("fake-line"));
}

}  // namespace cambench::test
