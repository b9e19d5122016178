# Golden transcripts of `mtc200-cli restart` (sourced by cli_restart.sh and
# scripts/update-golden.sh restart; not a test itself).
#
# A case is tests/golden/restart/NAME.args: one line with everything after
# `restart` (the program first: a NAME.nc of the directory or a program
# number, then the options), the expected transcript NAME.json =
# {"exit_code": N, "output": <the --json document>}, canonical as in
# golden.bash. Cases run in tests/golden/restart, so `--programs programs`
# names the test library there.
source "$(dirname "${BASH_SOURCE[0]}")/golden.bash"

# restart_transcript DIR NAME: prints the canonical transcript of case NAME.
restart_transcript() {
  local dir="$1" name="$2" args=() rc=0 out
  read -r -a args <"$dir/$name.args" || true
  out="$(cd "$dir" && timeout 60 "$MTC_CLI" --json restart "${args[@]}")" || rc=$?
  printf '%s' "$out" | python3 -c "$GOLDEN_CANONICAL_PY"'
import sys
rc = int(sys.argv[1])
text = sys.stdin.read()
try:
    doc = json.loads(text)
except ValueError as e:
    doc = {"invalid_json": str(e), "text": text[:2000]}
dump({"exit_code": rc, "output": doc})' "$rc"
}
