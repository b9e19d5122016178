#!/usr/bin/env bash
# Regenerates the expected transcripts of the CLI golden tests
# (tests/golden/cli/NAME.json) from the current mtc200-cli. Review the diff
# before committing: a golden file is a statement of correct behaviour.
#   scripts/update-golden.sh [NAME...]      default: every case
# MTC_CLI selects the binary (default build/release/app/mtc200-cli).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MTC_CLI="${MTC_CLI:-$here/build/release/app/mtc200-cli}"
export MTC_CLI="$(realpath "$MTC_CLI" 2>/dev/null || echo "$MTC_CLI")"
[ -x "$MTC_CLI" ] || { echo "update-golden: no mtc200-cli at $MTC_CLI (build first or set MTC_CLI)" >&2; exit 2; }
source "$here/tests/cli/golden.bash"
dir="$here/tests/golden/cli"
names=("$@")
if [ "${#names[@]}" -eq 0 ]; then
  for program in "$dir"/*.nc; do names+=("$(basename "$program" .nc)"); done
fi
for name in "${names[@]}"; do
  golden_transcript "$dir" "$name" >"$dir/$name.json"
  echo "updated $name.json (exit $(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["exit_code"])' "$dir/$name.json"))"
done
