# Shared helpers of the CLI shell tests (sourced; not a test itself).
# Environment from tests/CMakeLists.txt: MTC_CLI, MTC_GOLDEN, MTC_SOURCE_DIR.
set -uo pipefail

: "${MTC_CLI:?MTC_CLI must point to mtc200-cli}"
: "${MTC_SOURCE_DIR:?MTC_SOURCE_DIR must point to the repository}"
MTC_GOLDEN="${MTC_GOLDEN:-$MTC_SOURCE_DIR/tests/golden}"
command -v python3 >/dev/null || { echo "python3 is needed for the JSON checks"; exit 1; }

TEST_TMP="$(mktemp -d)"
trap 'rm -rf "$TEST_TMP"' EXIT
PASSED=0
FAILED=0
OUT=""
ERR=""
RC=0

# cli ARGS...: runs mtc200-cli (bounded by 60 s); sets OUT, ERR and RC.
cli() {
  timeout 60 "$MTC_CLI" "$@" >"$TEST_TMP/out" 2>"$TEST_TMP/err"
  RC=$?
  OUT="$(cat "$TEST_TMP/out")"
  ERR="$(cat "$TEST_TMP/err")"
}

pass() { PASSED=$((PASSED + 1)); echo "ok   - $1"; }
fail() {
  FAILED=$((FAILED + 1)); echo "FAIL - $1"
  echo "       exit $RC; stdout: ${OUT:0:600}"; echo "       stderr: ${ERR:0:400}"
}

# expect_rc CODE NAME ARGS...: runs the CLI and checks the exit code.
expect_rc() {
  local code="$1" name="$2"; shift 2
  cli "$@"
  if [ "$RC" = "$code" ]; then pass "$name (exit $code)"; else fail "$name: expected exit $code"; fi
}

# json_check NAME PYTHON_EXPRESSION: evaluates the expression with `d` = the
# JSON document in OUT; passes when it is true.
json_check() {
  local name="$1" expr="$2"
  if printf '%s' "$OUT" | python3 -c '
import json, sys
d = json.load(sys.stdin)
sys.exit(0 if ('"$expr"') else 1)' 2>"$TEST_TMP/pyerr"; then
    pass "$name"
  else
    fail "$name: $expr $(head -c 300 "$TEST_TMP/pyerr")"
  fi
}

# text_check NAME PATTERN: passes when stdout+stderr match the grep pattern.
text_check() {
  if printf '%s\n%s' "$OUT" "$ERR" | grep -- "$2" >/dev/null; then pass "$1"; else fail "$1: no '$2'"; fi
}

# finish: prints the summary line and sets the exit code.
finish() {
  echo "$PASSED passed, $FAILED failed"
  [ "$FAILED" -eq 0 ]
}
