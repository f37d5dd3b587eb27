#!/usr/bin/env bash
# Quick start: install what is missing, build (Release), start the GUI on the default scene.
# Arguments are passed on to sculptline (see ../shared/interfaces.md for the flags).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
"$root/scripts/setup.sh"
exec "$root/build/sculptline" "$@"
