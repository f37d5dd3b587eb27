#!/usr/bin/env bash
# Same set-up as run.sh, then the whole test suite through ctest (GUI tests run under xvfb-run).
# Arguments are passed on to ctest (e.g. ./test.sh -R bspline).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
"$root/scripts/setup.sh"
jobs=$(nproc 2>/dev/null || echo 2)
cd "$root/build"
exec ctest --output-on-failure --parallel "$jobs" "$@"
