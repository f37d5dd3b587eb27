#!/usr/bin/env bash
# Shared set-up for run.sh and test.sh: install missing Debian packages (list in
# scripts/debian-packages.txt), configure and build Sculptline in Release into build/.
# Idempotent: installs nothing and rebuilds nothing when nothing changed.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

"$root/scripts/install-packages.sh" scripts/debian-packages.txt

# ccache (in the package list) keeps compiled objects between clones: paths are hashed relative to
# this checkout (CCACHE_BASEDIR, no working directory in the hash), so a fresh clone anywhere reuses
# what an earlier build of the same sources compiled. A missing or cold cache only costs the compile.
export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=true
jobs=$(nproc 2>/dev/null || echo 2)
if [[ ! -f build/CMakeCache.txt ]]; then
  launcher=()
  if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}"
fi
cmake --build build --parallel "$jobs"
