#!/usr/bin/env bash
# mtc200-panel --help and --version without any display (issue 20 §1/§5):
# no QT_QPA_PLATFORM, no DISPLAY, no WAYLAND_DISPLAY; usage on stdout, exit 0.
set -u
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
unset QT_QPA_PLATFORM DISPLAY WAYLAND_DISPLAY

timeout 30 "$MTC_PANEL" --help >"$out/help" 2>"$out/err"
check "--help exits 0 without a display" "[ $? -eq 0 ]"
check "--help prints the usage" "grep -q '^Usage: .*mtc200-panel' '$out/help'"
check "--help names --machine and --speed" "grep -q -- '--machine <FILE>' '$out/help' && grep -q -- '--speed' '$out/help'"
check "--help writes no error" "[ ! -s '$out/err' ]"
timeout 30 "$MTC_PANEL" -h >"$out/h" 2>&1
check "-h is --help" "[ $? -eq 0 ] && cmp -s '$out/help' '$out/h'"
timeout 30 "$MTC_PANEL" --version >"$out/version" 2>"$out/err"
check "--version exits 0 without a display" "[ $? -eq 0 ]"
check "--version prints name and version" "grep -Eq '^mtc200-panel [0-9]+\.[0-9]+\.[0-9]+$' '$out/version'"
timeout 30 "$MTC_PANEL" --help --no-such-option >"$out/x" 2>"$out/err"
check "--help with an unknown option: exit 2, named" "[ $? -eq 2 ] && grep -q no-such-option '$out/err'"
exit $fail
