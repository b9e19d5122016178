#!/usr/bin/env bash
# Regenerates the expected transcripts of the restart golden tests
# (tests/golden/restart/NAME.json) from the current mtc200-cli. Review the
# diff before committing: a golden file is a statement of correct behaviour.
#   scripts/update-golden-restart.sh [NAME...]      default: every case
# MTC_CLI selects the binary (default build/release/app/mtc200-cli).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MTC_CLI="${MTC_CLI:-$here/build/release/app/mtc200-cli}"
export MTC_CLI="$(realpath "$MTC_CLI" 2>/dev/null || echo "$MTC_CLI")"
[ -x "$MTC_CLI" ] || { echo "update-golden-restart: no mtc200-cli at $MTC_CLI" >&2; exit 2; }
source "$here/tests/cli/restart_golden.bash"
dir="$here/tests/golden/restart"
names=("$@")
if [ "${#names[@]}" -eq 0 ]; then
  for args in "$dir"/*.args; do names+=("$(basename "$args" .args)"); done
fi
for name in "${names[@]}"; do
  restart_transcript "$dir" "$name" >"$dir/$name.json"
  echo "updated $name.json (exit $(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["exit_code"])' "$dir/$name.json"))"
done
