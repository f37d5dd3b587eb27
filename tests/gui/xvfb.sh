#!/usr/bin/env bash
# Runs a command on an Xvfb display of its own and returns its status. Xvfb picks a free display
# number itself (-displayfd), so GUI tests run in parallel without the race of `xvfb-run -a`, which
# can hand two tests starting at once the same number (one of them then dies within seconds).
# Usage: xvfb.sh COMMAND [ARGS...]
set -uo pipefail
dir=$(mktemp -d)
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>"$dir/display" 2>"$dir/xvfb.log" &
server=$!
cleanup() { kill "$server" 2>/dev/null; wait "$server" 2>/dev/null; rm -rf "$dir"; }
trap cleanup EXIT
# Xvfb writes the number once it listens; 30 s covers a loaded machine.
for _ in $(seq 300); do
  [[ -s "$dir/display" ]] && break
  kill -0 "$server" 2>/dev/null || { echo "xvfb.sh: Xvfb did not start: $(cat "$dir/xvfb.log")" >&2; exit 1; }
  sleep 0.1
done
[[ -s "$dir/display" ]] || { echo "xvfb.sh: Xvfb gave no display number" >&2; exit 1; }
export DISPLAY=":$(head -n1 "$dir/display")"
"$@"
status=$?
exit "$status"
