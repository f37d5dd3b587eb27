#include "solvers/stroke/prime.h"

#include "solvers/stroke/shape_recognizer.h"
#include "solvers/stroke/stroke_synthesis.h"

namespace sculptline::solvers::stroke {

void primeStrokeFit() noexcept
{
    // A two-and-a-half-turn spiral with digitizer noise: smooth, curving throughout, so the pass
    // runs the conditioning, the dynamic sampling, the least squares and its knot search, and the
    // recognizer's primitive fits.
    constexpr int kSamples = 1000;
    constexpr double kSize = 250.0, kTurns = 2.5, kNoise = 0.25;
    DrawOptions d;
    d.noise = kNoise;
    try {
        (void)recognizeStroke(drawWithSamples(spiralShape(kSize, kTurns), kSamples, d));
    } catch (...) {
        // Priming is only an optimization: a failure here shows again, reported, on a real stroke.
    }
}

}  // namespace sculptline::solvers::stroke
