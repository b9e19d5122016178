#!/usr/bin/env bash
# Brings the panel's Qt Linguist catalogues up to date with the sources
# (docs/DECISIONS.md D-018): new tr() texts appear as unfinished in
# resources/translations/mtc200_de.ts (translate them with `linguist` or by
# hand), texts gone from the sources are dropped. The English catalogue holds
# the plural forms only: English is the source language.
# The test `i18n.translations_complete` fails while a German text is missing.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
lupdate="${LUPDATE:-$(command -v lupdate || echo /usr/lib/qt5/bin/lupdate)}"
cd "$here"
common=(-no-obsolete -locations none -extensions cpp,h -I . -source-language en)
"$lupdate" "${common[@]}" -target-language de app hmi screens \
  -ts resources/translations/mtc200_de.ts
"$lupdate" "${common[@]}" -target-language en -pluralonly app hmi screens \
  -ts resources/translations/mtc200_en.ts
