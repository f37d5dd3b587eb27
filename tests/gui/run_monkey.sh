#!/usr/bin/env bash
# The monkey test: random input (scripts/monkey_session.py, fixed seed) replayed in the real window
# under Xvfb. Passes when sculptline neither crashes nor hangs, exits 0, saves a document whose
# numbers are finite and whose curves are not degenerate (check_saved_document.py), and that
# document opens again.
# Usage: run_monkey.sh SCULPTLINE_EXE SOURCE_DIR OUT_DIR SEED SECONDS
set -uo pipefail
exe=$1 src=$2 out=$3 seed=$4 seconds=$5
mkdir -p "$out"
session="$out/monkey_$seed.json" saved="$out/monkey_$seed.saved.json"
rm -f "$session" "$saved"
python3 "$src/scripts/monkey_session.py" --seed "$seed" --seconds "$seconds" --output "$session" || exit 1
# The session lasts $seconds; anything past four times that (and a minute for start-up) is a hang.
limit=$(python3 -c "print(int(4 * $seconds + 60))")
"$src/tests/gui/xvfb.sh" timeout --signal=KILL "$limit" "$exe" --replay "$session" --save "$saved" --quit
status=$?
if [[ $status -ne 0 ]]; then
  echo "monkey seed $seed: sculptline exited with status $status (137: killed after ${limit} s, a hang); reproduce with:" >&2
  echo "  python3 scripts/monkey_session.py --seed $seed --seconds $seconds -o m.json && tests/gui/xvfb.sh $exe --replay m.json --quit" >&2
  exit 1
fi
python3 "$src/tests/gui/check_saved_document.py" "$saved" || exit 1
"$src/tests/gui/xvfb.sh" timeout --signal=KILL 120 "$exe" "$saved" --quit || { echo "monkey seed $seed: the saved document does not open" >&2; exit 1; }
echo "monkey seed $seed: $(python3 -c "import json; print(len(json.load(open('$session'))['events']))") events replayed, document saved and reopened"
