#!/usr/bin/env bash
# mtc200-panel options offscreen: --screenshot for each screen, bad options exit 2.
set -u
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export XDG_CONFIG_HOME="$out/config"

for screen in menu programs signals help tools offsets; do
  "$MTC_PANEL" --screen "$screen" --screenshot "$out/$screen.png" 2>"$out/err"
  rc=$?
  check "screenshot of $screen exits 0" "[ $rc -eq 0 ]"
  check "screenshot of $screen is a PNG" "head -c 8 '$out/$screen.png' | od -An -c | grep 'P   N   G' >/dev/null"
  check "screenshot of $screen is not tiny" "[ \$(stat -c %s '$out/$screen.png') -gt 5000 ]"
done

"$MTC_PANEL" --process 1 --program 1 --screen programs --screenshot "$out/lathe.png" 2>"$out/err"
check "--process 1 --program 1 works" "[ $? -eq 0 ]"

"$MTC_PANEL" --screen nosuchscreen --screenshot "$out/x.png" 2>"$out/err"
check "unknown screen exits 2" "[ $? -eq 2 ]"
check "unknown screen is named" "grep -q nosuchscreen '$out/err'"
"$MTC_PANEL" --process 7 --screenshot "$out/x.png" 2>"$out/err"
check "unknown process exits 2" "[ $? -eq 2 ]"
"$MTC_PANEL" --process abc --screenshot "$out/x.png" 2>"$out/err"
check "bad process number exits 2" "[ $? -eq 2 ]"
"$MTC_PANEL" --machine /nonexistent.cfg --screenshot "$out/x.png" 2>"$out/err"
check "missing machine file exits 2" "[ $? -eq 2 ] && grep -q nonexistent '$out/err'"
printf '[process 0]\nname = X\nbogus = 1\n' >"$out/bad.cfg"
"$MTC_PANEL" --machine "$out/bad.cfg" --screenshot "$out/x.png" 2>"$out/err"
check "bad machine file exits 2 with its line" "[ $? -eq 2 ] && grep -q 'line 3' '$out/err'"
"$MTC_PANEL" --no-such-option 2>"$out/err"
check "unknown option exits 2" "[ $? -eq 2 ]"
"$MTC_PANEL" --program 555 --screenshot "$out/x.png" 2>"$out/err"
check "missing program number exits 2" "[ $? -eq 2 ]"
"$MTC_PANEL" --screenshot /nonexistent-dir/x.png 2>"$out/err"
check "unwritable screenshot exits 2" "[ $? -eq 2 ]"
exit $fail
