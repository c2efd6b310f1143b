// libFuzzer target for the Compax3 answer parser: Compax3Backend cuts the
// byte stream into lines, parseCompax3Reply reads each. The same function
// runs in normal builds through fuzz_compax3_reply_replay_main.cpp
// (fuzz_compax3_reply_replay).
#include "comm/compax3/compax3_backend.h"
#include "comm/compax3/compax3_syntax.h"
#include "fuzz_check.h"

#include <cstdint>

using namespace cambench::comm;

namespace {

// Every line handed up holds no CR; a parsed reply is '>', an error number
// of four hex digits, or printable text without the RS485 mark in front.
void checkStep(const BackendStep& step) {
    for (const Incoming& in : step.incoming) {
        FUZZ_CHECK(in.kind == Incoming::Message);
        FUZZ_CHECK(!in.message.contains('\r'));
        FUZZ_CHECK(in.wire.endsWith('\r'));
        const cambench::Result<Compax3Reply> reply = parseCompax3Reply(in.message);
        if (!reply) continue;
        if (reply->kind == Compax3Reply::Error)
            FUZZ_CHECK(reply->code >= 0 && reply->code <= 0xFFFF);
        if (reply->kind == Compax3Reply::Value) {
            FUZZ_CHECK(!reply->text.isEmpty());
            for (QChar c : reply->text) FUZZ_CHECK(c.unicode() >= 0x20 && c.unicode() <= 0x7E);
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    // First byte: RS232 or an RS485 address.
    Compax3Backend backend(data[0] < 100 ? int(data[0]) : -1);
    cambench::comm::Request request;
    request.message = "O680,5";
    backend.beginRequest(request);
    const BackendStep sent = backend.startAttempt(request, 1, 0);
    FUZZ_CHECK(sent.sent && sent.write.endsWith('\r'));
    std::size_t at = 1;
    while (at < size) {
        const std::size_t chunk = std::min<std::size_t>(size - at, 1 + data[at] % 8);
        checkStep(backend.feed(
            QByteArrayView(reinterpret_cast<const char*>(data + at), qsizetype(chunk)), 0));
        at += chunk;
    }
    (void)backend.resetInput();
    return 0;
}
