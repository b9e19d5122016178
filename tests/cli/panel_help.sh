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

# The language of the texts (D-018): --lang, else the desk's setting, else
# the locale's UI language (German for de_*). Qt's own option lines stay English.
unset LANGUAGE LC_MESSAGES
export XDG_CONFIG_HOME="$out/config"
LC_ALL=de_DE.UTF-8 timeout 30 "$MTC_PANEL" --help >"$out/de" 2>&1
check "German desk: German option texts" "grep -q 'Maschinenkonfigurationsdatei' '$out/de' && grep -q -- '--lang <de|en>' '$out/de'"
LC_ALL=de_DE.UTF-8 timeout 30 "$MTC_PANEL" --lang en --help >"$out/en" 2>&1
check "German desk, --lang en: English" "grep -q 'Machine configuration file' '$out/en' && ! grep -q 'Maschinen' '$out/en'"
LC_ALL=C.UTF-8 LANG=C.UTF-8 timeout 30 "$MTC_PANEL" --help >"$out/c" 2>&1
check "other desk: English" "grep -q 'Machine configuration file' '$out/c'"
LC_ALL=C.UTF-8 LANG=C.UTF-8 timeout 30 "$MTC_PANEL" --lang de --help >"$out/c-de" 2>&1
check "--lang de: German" "grep -q 'Maschinenkonfigurationsdatei' '$out/c-de'"
mkdir -p "$out/config/MTC200Sim"
printf '[panel]\nlanguage=de\n' >"$out/config/MTC200Sim/mtc200-panel.conf"
LC_ALL=C.UTF-8 LANG=C.UTF-8 timeout 30 "$MTC_PANEL" --help >"$out/stored" 2>&1
check "the desk's stored language: German" "grep -q 'Maschinenkonfigurationsdatei' '$out/stored'"
QT_QPA_PLATFORM=offscreen timeout 30 "$MTC_PANEL" --lang fr --screenshot "$out/fr.png" >"$out/fr" 2>&1
check "--lang fr: exit 2, named (in the desk's German)" "[ $? -eq 2 ] && grep -q 'braucht de oder en, nicht .fr.' '$out/fr'"
exit $fail
