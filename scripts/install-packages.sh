#!/usr/bin/env bash
# install-packages.sh LIST...: installs the Debian packages named in the LIST files (one a line, #
# comments) that are not installed yet; apt-get update first, and nothing at all when none is missing.
# Used by setup.sh (scripts/debian-packages.txt) and sanitize.sh (scripts/debian-packages-sanitize.txt).
set -euo pipefail
wanted=()
for list in "$@"; do
  mapfile -t -O "${#wanted[@]}" wanted < <(grep -vE '^\s*(#|$)' "$list")
done
missing=()
for pkg in "${wanted[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$pkg")
done
if ((${#missing[@]})); then
  echo "sculptline setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y "${missing[@]}"
fi
