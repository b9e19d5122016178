# Golden transcripts of mtc200-cli (sourced by cli_golden.sh and
# scripts/update-golden.sh; not a test itself).
#
# A case is tests/golden/cli/NAME.nc, optionally NAME.args (one line: options,
# and first the command when it is not `run`), and the expected transcript
# NAME.json = {"exit_code": N, "output": <the --json document>}, canonical
# (keys sorted, indent 1). The program is run from tests/golden/cli under its
# relative name, so messages do not depend on where the repository lies.
# Numbers are compared rounded to 6 decimals (1 nm, 1 µs): the order of
# floating-point sums may change without the behaviour changing.

# The Python canonicaliser both functions share.
GOLDEN_CANONICAL_PY='
import json
def canonical(value):
    if isinstance(value, float):
        rounded = round(value, 6)
        if rounded == int(rounded) and abs(rounded) < 1e15:
            return int(rounded)
        return rounded
    if isinstance(value, list):
        return [canonical(v) for v in value]
    if isinstance(value, dict):
        return {k: canonical(v) for k, v in value.items()}
    return value
def dump(doc):
    print(json.dumps(canonical(doc), sort_keys=True, indent=1))
'

# golden_transcript DIR NAME: prints the canonical transcript of case NAME.
golden_transcript() {
  local dir="$1" name="$2" args=() command=run rc=0 out
  if [ -f "$dir/$name.args" ]; then
    read -r -a args <"$dir/$name.args" || true
  fi
  if [ "${#args[@]}" -gt 0 ] && { [ "${args[0]}" = run ] || [ "${args[0]}" = check ]; }; then
    command="${args[0]}"
    args=("${args[@]:1}")
  fi
  out="$(cd "$dir" && timeout 60 "$MTC_CLI" --json "${args[@]}" "$command" "$name.nc")" || rc=$?
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

# golden_canonical FILE: prints FILE canonicalised the same way.
golden_canonical() {
  python3 -c "$GOLDEN_CANONICAL_PY"'
import sys
dump(json.load(open(sys.argv[1])))' "$1"
}
