#!/usr/bin/env bash
# Exit code 2 for every usage and file error of CLI-CONTRACT.md, 0 for help.
source "$(dirname "$0")/common.bash"
demo="$MTC_SOURCE_DIR/resources/programs/N1010001.DAT"

expect_rc 0 "--help" --help
text_check "help lists check and run" "check FILE|PROG"
text_check "help lists restart" "restart FILE|PROG --target PATH"
text_check "help lists md" "md set PAGE ELEMENT VALUE"
text_check "help lists compile" "compile FILE|PROG \[-o OUT.NCO\]"
expect_rc 0 "help command" help
expect_rc 0 "--version" --version
text_check "version text" "mtc200-cli"

expect_rc 2 "no arguments"
expect_rc 2 "unknown command" frobnicate
text_check "unknown command named" "unknown command 'frobnicate'"
expect_rc 2 "unknown option" run --turbo "$demo"
text_check "unknown option named" "unknown option '--turbo'"
expect_rc 2 "unknown global option before the command" --colour run "$demo"
expect_rc 2 "option value missing" run "$demo" --max-blocks
for bad in 0 -5 abc 1e3 12x "" 99999999999999999999; do
  expect_rc 2 "bad --max-blocks '$bad'" run --max-blocks "$bad" "$demo"
done
expect_rc 2 "bad --max-blocks=abc" run --max-blocks=abc "$demo"
expect_rc 2 "bad --process" --process x run "$demo"
expect_rc 2 "negative --process" --process -1 run "$demo"
expect_rc 2 "--json takes no value" --json=yes run "$demo"
expect_rc 2 "run without a program" run
expect_rc 2 "check without a program" check
expect_rc 2 "run with two programs" run "$demo" "$demo"
expect_rc 2 "--no-motion with check" check --no-motion "$demo"

# File errors.
expect_rc 2 "missing file" run "$TEST_TMP/does-not-exist.nc"
text_check "missing file message" "no such file"
expect_rc 2 "directory as program" run "$TEST_TMP"
text_check "directory message" "not a regular file"
expect_rc 2 "missing program number" run 77
text_check "missing program number message" "program 77 of process 0 not found"
expect_rc 2 "missing program directory" --programs "$TEST_TMP/none" run 1
printf 'N0000 G1 X1 F100\n' >"$TEST_TMP/locked.nc"
chmod 000 "$TEST_TMP/locked.nc"
if [ "$(id -u)" -ne 0 ]; then
  expect_rc 2 "unreadable file" run "$TEST_TMP/locked.nc"
  text_check "unreadable file message" "cannot read"
else
  pass "unreadable file: skipped as root (root reads every file)"
fi
chmod 644 "$TEST_TMP/locked.nc"

# compile: a missing program file is a file error (tests/cli/cli_compile.sh has the rest).
expect_rc 2 "compile of a missing file" compile "$TEST_TMP/none.DAT"

# With --json, usage errors still print exactly one JSON document.
expect_rc 2 "usage error with --json" --json run --max-blocks 0 "$demo"
json_check "usage error JSON" 'd["status"] == "error" and d["diagnostics"][0]["code"] == "CLI_USAGE"'
expect_rc 2 "missing file with --json" --json run "$TEST_TMP/nope.nc"
json_check "file error JSON" 'd["status"] == "error" and d["diagnostics"][0]["code"] == "CLI_FILE_UNREADABLE"'
json_check "file error JSON has diagnostic keys" 'all(k in d["diagnostics"][0] for k in ("severity","code","program","block","line","message","details"))'
finish
