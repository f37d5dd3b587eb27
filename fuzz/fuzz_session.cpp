// The replay-session reader (ui/replay_session.h): bytes -> parseReplaySession, what `sculptline
// --replay FILE` does before Qt starts. Rejected input (InputError) is fine; an accepted session
// must respect the reader's own limits.
#include "fuzz/fuzz_target.h"
#include "ui/replay_session.h"

#include "solvers/io/geometry_json.h"

#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace sculptline;
    const std::string text(reinterpret_cast<const char*>(data), size);
    ui::ReplaySession session;
    try {
        session = ui::parseReplaySession(text);
    } catch (const solvers::io::InputError& e) {
        fuzz::noteRejected(e.what());
        return 0;
    } catch (const std::exception& e) {
        fuzz::fuzzFailure("session", std::string("not an InputError: ") + e.what());
    }
    if (session.events.size() > ui::kMaxReplayEvents) fuzz::fuzzFailure("session", "more events than kMaxReplayEvents");
    for (const ui::ReplayEvent& e : session.events) {
        if (e.t > ui::kMaxReplayMs || e.waitMs < 0 || e.waitMs > ui::kMaxReplayMs)
            fuzz::fuzzFailure("session", "a time outside [0, kMaxReplayMs] was accepted");
    }
    return 0;
}
