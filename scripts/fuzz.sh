#!/usr/bin/env bash
# fuzz.sh [options] TARGET...|all: libFuzzer campaigns on the fuzz targets of fuzz/ (build-asan/:
# clang, AddressSanitizer, UndefinedBehaviorSanitizer; built here by scripts/build-asan.sh).
#
#   --time S       stop each target after S seconds (default 60 when --runs is not given)
#   --runs N       stop each target after N executions (whichever of the two comes first)
#   --jobs J       J parallel fuzzing processes per target (libFuzzer -fork=J; default 1)
#   --rss-mb M     memory limit per process, MB (default 2048)
#   --timeout T    an input running longer than T seconds is a hang (default 1)
#   --seed N       libFuzzer's random seed (default: from the clock); a fixed seed makes a --runs
#                  campaign repeat exactly
#   --artifacts D  where findings go (default build-asan/fuzz-artifacts/<target>/)
#   --no-build     use the programs in build-asan/fuzz as they are (e.g. two campaigns side by side)
#   --fresh        start from the seed corpus alone (default: also the corpus earlier runs grew in
#                  build-asan/fuzz-corpus/<target>/)
#   --list         print the target names
# Targets: document, session, iv-import (the .iv reference importer) and one per sculptline-cli
# subcommand (eval, fit, surface, ...).
# Seeds: tests/fuzz/corpus/<target>/ (never written to). Logs: build-asan/fuzz-logs/<target>.log.
# Exit status 1 if any target found something; the message says how to reproduce it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-asan"
seeds="$root/tests/fuzz/corpus"

seconds="" runs="" jobs=1 rss=2048 timeout=1 seed="" artifacts="" fresh=0 build_first=1 targets=()
while (($#)); do
  case "$1" in
    --time) seconds=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --rss-mb) rss=$2; shift 2 ;;
    --timeout) timeout=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --artifacts) artifacts=$2; shift 2 ;;
    --fresh) fresh=1; shift ;;
    --no-build) build_first=0; shift ;;
    --list) ls "$seeds"; exit 0 ;;
    -h|--help) sed -n '2,22p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "fuzz.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
((${#targets[@]})) || { echo "fuzz.sh: name targets or 'all' (see --list)" >&2; exit 2; }
if [[ " ${targets[*]} " == *" all "* ]]; then mapfile -t targets < <(ls "$seeds"); fi
for t in "${targets[@]}"; do
  [[ -d "$seeds/$t" ]] || { echo "fuzz.sh: no target '$t' (see --list)" >&2; exit 2; }
done

if ((build_first)); then "$root/scripts/build-asan.sh" "${targets[@]/#/fuzz-}"; fi

export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# OpenCASCADE's translators leak a little per process (scripts/lsan-occt.supp); the list of
# suppressions used stays off stderr, which the CLI tests expect empty.
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/scripts/lsan-occt.supp:print_suppressions=0}
mkdir -p "$build/fuzz-logs"
failed=()
printf '%-16s %12s %8s %10s  %s\n' target executions seconds exec/s result
for t in "${targets[@]}"; do
  out=${artifacts:-$build/fuzz-artifacts}/$t
  mkdir -p "$out"
  if ((fresh)); then
    corpus=$(mktemp -d)
  else
    corpus="$build/fuzz-corpus/$t"
    mkdir -p "$corpus"
  fi
  limit=()
  [[ -n $runs ]] && limit+=(-runs="$runs")
  [[ -n $seconds || -z $runs ]] && limit+=(-max_total_time="${seconds:-60}")
  fork=()
  ((jobs > 1)) && fork=(-fork="$jobs")
  [[ -n $seed ]] && fork+=(-seed="$seed")
  # A target's own dictionary (fuzz/<target>.dict: the .iv importer's Inventor keywords), else the JSON one.
  dict="$root/fuzz/$t.dict"
  [[ -f $dict ]] || dict="$root/fuzz/sculptline.dict"
  log="$build/fuzz-logs/$t.log"
  start=$(date +%s.%N)
  status=0
  "$build/fuzz/fuzz-$t" "${limit[@]}" "${fork[@]}" -timeout="$timeout" -rss_limit_mb="$rss" \
    -dict="$dict" -artifact_prefix="$out/" -print_final_stats=1 \
    "$corpus" "$seeds/$t" >"$log" 2>&1 || status=$?
  elapsed=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN {print b - a}')
  ((fresh)) && rm -rf "$corpus"
  # Executions: the final stats, else (fork mode, or a finding) the last progress line "#N".
  execs=$( (grep -ao 'stat::number_of_executed_units: *[0-9]*' "$log" || true) | awk '{s += $2} END {print s + 0}')
  if ((execs == 0)); then
    execs=$( (grep -aoE '^#[0-9]+' "$log" || true) | tail -1 | tr -d '#')
    execs=${execs:-0}
  fi
  result=ok
  if ((status != 0)); then
    result="FINDING (log: $log)"
    failed+=("$t")
  fi
  printf '%-16s %12s %8.0f %10.0f  %s\n' "$t" "$execs" "$elapsed" "$(awk -v n="$execs" -v s="$elapsed" 'BEGIN {print n / s}')" "$result"
done
if ((${#failed[@]})); then
  cat >&2 <<MSG
fuzz.sh: findings in ${failed[*]}; the inputs are in ${artifacts:-$build/fuzz-artifacts}/<target>/.
Reproduce one:   $build/fuzz/fuzz-<target> <artifact>     (with sanitizers)
                 build/fuzz/fuzz-<target> <artifact>         (Release, GCC: the replay program)
Then fix it and keep the input as a regression seed: cp <artifact> tests/fuzz/corpus/<target>/crash-<what>.json
MSG
  exit 1
fi
