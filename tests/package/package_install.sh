#!/usr/bin/env bash
# The .deb CPack builds from this build tree (issue 20 §5): its control data,
# its files, and both programs started from a temporary root it was unpacked
# into: mtc200-cli --version and a run, mtc200-panel --help and --version
# without a display, the panel offscreen taking a screenshot.
set -uo pipefail
build="${MTC_BUILD_DIR:?}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
failures=0
check() {  # check NAME COMMAND...
  if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; failures=$((failures + 1)); fi
}

if ! (cd "$build" && cpack -G DEB -B "$tmp/out") >"$tmp/cpack.log" 2>&1; then
  cat "$tmp/cpack.log"
  echo "FAIL cpack"
  exit 1
fi
deb="$(ls "$tmp"/out/*.deb 2>/dev/null | head -n 1)"
check "one .deb was built" "[ -n '$deb' ] && [ -f '$deb' ]"
[ -n "$deb" ] || exit 1
dpkg-deb --info "$deb" >"$tmp/info"
check "package name" "grep -q '^ Package: mtc200-panel$' '$tmp/info'"
check "version of the project" "grep -q '^ Version: $MTC_VERSION$' '$tmp/info'"
check "depends on the Qt 5 widgets library" "grep -q '^ Depends:.*libqt5widgets5' '$tmp/info'"

root="$tmp/root"
dpkg-deb -x "$deb" "$root"
for f in usr/bin/mtc200-cli usr/bin/mtc200-panel; do
  check "$f is an executable" "[ -x '$root/$f' ]"
done
check "desktop entry" "grep -q '^Exec=mtc200-panel$' '$root/usr/share/applications/mtc200-panel.desktop'"
check "desktop entry names its icon" "grep -q '^Icon=mtc200-panel$' '$root/usr/share/applications/mtc200-panel.desktop'"
check "icon" "grep -q '<svg' '$root/usr/share/icons/hicolor/scalable/apps/mtc200-panel.svg'"
check "man page of mtc200-cli" "zcat '$root/usr/share/man/man1/mtc200-cli.1.gz' | grep -q '^.TH MTC200-CLI 1'"
check "man page names the version" "zcat '$root/usr/share/man/man1/mtc200-cli.1.gz' | grep -q '$MTC_VERSION'"

cli="$root/usr/bin/mtc200-cli"
panel="$root/usr/bin/mtc200-panel"
check "installed mtc200-cli --version" "'$cli' --version | grep -q '$MTC_VERSION'"
check "installed mtc200-cli runs a demo program" "'$cli' run 1 --no-motion >'$tmp/run' 2>&1"
check "installed mtc200-panel --version without a display" \
  "env -u DISPLAY -u WAYLAND_DISPLAY QT_QPA_PLATFORM= '$panel' --version | grep -q '$MTC_VERSION'"
check "installed mtc200-panel --help without a display" \
  "env -u DISPLAY -u WAYLAND_DISPLAY QT_QPA_PLATFORM= '$panel' --help | grep -q -- '--screenshot'"
check "installed mtc200-panel starts offscreen" \
  "QT_QPA_PLATFORM=offscreen '$panel' --screen position --screenshot '$tmp/shot.png' 2>'$tmp/panel.err'"
check "its screenshot is a PNG" "head -c 8 '$tmp/shot.png' | od -An -c | grep -q 'P   N   G'"
# The translations are compiled into the panel (D-018): German from the package too.
check "installed mtc200-panel speaks German" \
  "env -u DISPLAY -u WAYLAND_DISPLAY QT_QPA_PLATFORM= '$panel' --lang de --help | grep -q 'Maschinenkonfigurationsdatei'"
check "installed mtc200-panel offscreen in German" \
  "QT_QPA_PLATFORM=offscreen '$panel' --lang de --screen position --screenshot '$tmp/shot-de.png' 2>'$tmp/panel-de.err'"

[ "$failures" -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
echo "package: all checks passed"
