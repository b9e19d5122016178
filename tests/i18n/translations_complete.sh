#!/usr/bin/env bash
# Every visible text of the panel has a German translation (issue 20 §1,
# docs/DECISIONS.md D-018): lupdate brings a copy of each committed catalogue
# up to date with the sources, check_catalogue.py fails on any text without
# a finished translation and on texts the sources no longer have. The test
# first proves that it catches a new untranslated tr() text.
# Needs MTC_LUPDATE (lupdate) and MTC_SOURCE_DIR.
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
src="${MTC_SOURCE_DIR:?}"
lupdate="${MTC_LUPDATE:?}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
status=0
common=(-locations none -extensions cpp,h -I "$src" -source-language en)

# lupdate over the panel's sources (and `extra` paths) into a copy of catalogue $1.
refresh() {
  local catalogue="$1" out="$2" language="$3"; shift 3
  cp "$src/resources/translations/$catalogue" "$out"
  "$lupdate" "${common[@]}" -target-language "$language" "$@" \
    "$src/app" "$src/hmi" "$src/screens" -ts "$out" >"$tmp/lupdate.log" 2>&1 ||
    { cat "$tmp/lupdate.log"; echo "FAIL: lupdate failed"; exit 1; }
}

# 1. The check can fail: a screen with one new text nobody translated.
mkdir -p "$tmp/probe"
cat >"$tmp/probe/ProbeScreen.cpp" <<'CPP'
#include <QCoreApplication>
struct ProbeScreen { Q_DECLARE_TR_FUNCTIONS(ProbeScreen) };
QString probeLabel() { return ProbeScreen::tr("A soft key nobody translated"); }
CPP
refresh mtc200_de.ts "$tmp/probe.ts" de "$tmp/probe"
if python3 "$here/check_catalogue.py" "$tmp/probe.ts" >"$tmp/probe.out"; then
  echo "FAIL: a new untranslated text went unnoticed"; status=1
elif grep -q "no translation: 'A soft key nobody translated'" "$tmp/probe.out"; then
  echo "ok: a new untranslated text is reported"
else
  cat "$tmp/probe.out"; echo "FAIL: the probe text is not named"; status=1
fi

# 2. The German catalogue is complete for the sources as they are.
refresh mtc200_de.ts "$tmp/de.ts" de
python3 "$here/check_catalogue.py" "$tmp/de.ts" || {
  echo "FAIL: run scripts/update-translations.sh and translate the texts above"; status=1; }

# 3. The English catalogue: the source language, plural forms only.
refresh mtc200_en.ts "$tmp/en.ts" en -pluralonly
python3 "$here/check_catalogue.py" "$tmp/en.ts" --plural-only || {
  echo "FAIL: run scripts/update-translations.sh and fill the plural forms above"; status=1; }

[ "$status" -eq 0 ] && echo "PASS: translations complete"
exit "$status"
