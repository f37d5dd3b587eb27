#pragma once
// Progress and cancellation of long conversions (a solid takes seconds at fine voxel sizes): the
// caller's callback is asked between stages and, inside OpenVDB's conversions, through their
// interrupter (openvdb::util::NullInterrupter), so a cancel stops the work within one stage step.
#include <functional>
#include <stdexcept>

namespace sculptline::solvers::volume {

/// Told the fraction done, in [0, 1]; returns false to cancel. Called from the thread doing the
/// work (and, inside OpenVDB, possibly from TBB's worker threads): it must be thread-safe and cheap.
using Progress = std::function<bool(double fraction)>;

/// Thrown by a conversion that its Progress callback cancelled; nothing of its result is returned.
class Cancelled : public std::runtime_error {
public:
    Cancelled() : std::runtime_error("cancelled") {}
};

/// Calls `progress` (when set) with `fraction`; @throws Cancelled when it answers false.
inline void reportProgress(const Progress& progress, double fraction)
{
    if (progress && !progress(fraction)) throw Cancelled();
}

}  // namespace sculptline::solvers::volume
