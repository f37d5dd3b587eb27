#!/usr/bin/env bash
# Shared set-up for run.sh and test.sh: install missing Debian packages (list in
# scripts/debian-packages.txt), configure and build Sculptline in Release into build/.
# Idempotent: installs nothing and rebuilds nothing when nothing changed.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

"$root/scripts/install-packages.sh" scripts/debian-packages.txt

jobs=$(nproc 2>/dev/null || echo 2)
if [[ ! -f build/CMakeCache.txt ]]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
fi
cmake --build build --parallel "$jobs"
