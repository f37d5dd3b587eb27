#pragma once
// Priming the pen-up path once per process (issue 15 §3). The first fit in a process pays for
// touching the fitter's heap and code for the first time: on the 2026-12-07 machine (AMD EPYC VM,
// bench/stroke_bench.cpp BM_StrokeFitCold) a 1,000-sample stroke's first fit took 3.8x its warm
// time, of which first-touch heap page faults were about 45 % of the excess, code page faults and
// the rest of the processor's first sight of the code about 35 %, and cold caches 20 %; the first
// fit runs 1 % more instructions than a warm one (callgrind), so no set-up of ours is to blame.
// An application that fits strokes primes once at start; its first pen-up then costs what any
// later one does (cold caches only: 1.5x warm on that machine).
namespace sculptline::solvers::stroke {

/// Recognizes (and so fits) a built-in free-hand stroke of 1,000 samples, the size of a slow
/// hand's stroke, once: the fitter's code is paged in and its heap grown to that size. Takes about
/// 1.5 ms; the result is discarded. Never throws.
void primeStrokeFit() noexcept;

}  // namespace sculptline::solvers::stroke
