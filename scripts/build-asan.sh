#!/usr/bin/env bash
# build-asan.sh [TARGET...]: installs what the sanitizer build needs, configures build-asan/ (once) and
# builds the given targets (default: all). The build: Debug, clang, AddressSanitizer +
# UndefinedBehaviorSanitizer + _GLIBCXX_ASSERTIONS + libFuzzer instrumentation
# (cmake/SculptlineSanitize.cmake), headless layers only (GUI and benchmarks off).
# Used by scripts/sanitize.sh (CI) and scripts/fuzz.sh.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
"$root/scripts/install-packages.sh" scripts/debian-packages.txt scripts/debian-packages-sanitize.txt

build=build-asan
# Objects are shared between clones through ccache (scripts/setup.sh says how).
export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=true
if [[ ! -f $build/CMakeCache.txt ]]; then
  launcher=()
  if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++ "${launcher[@]}" \
    -DSCULPTLINE_SANITIZE=ON -DSCULPTLINE_FUZZ=ON -DSCULPTLINE_BUILD_GUI=OFF -DSCULPTLINE_BUILD_BENCH=OFF
fi
# The whole build takes about NEED_GB of disk (line tables only, cmake/SculptlineSanitize.cmake). Say
# so up front: a full disk otherwise shows up as a compiler crash in the middle of the build.
need_gb=4
free_gb=$(df -Pk "$root" | awk 'NR==2 {print int($4 / 1048576)}')
if ((free_gb < need_gb)); then
  echo "build-asan.sh: only ${free_gb} GB free on the disk of $root; the sanitizer build needs about ${need_gb} GB" >&2
fi
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$build" --parallel "$(nproc 2>/dev/null || echo 2)" "${targets[@]}"
