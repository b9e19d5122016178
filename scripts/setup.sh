#!/usr/bin/env bash
# Installs the Debian packages the project needs (only the missing ones) and
# configures + builds the given CMake preset with Ninja.
# Usage: scripts/setup.sh [release|debug|asan|fuzz]
#        scripts/setup.sh tools   only the packages of scripts/fuzz.sh,
#                                 scripts/lint.sh and scripts/valgrind.sh
#        scripts/setup.sh bench   only the reference of scripts/bench.sh:
#                                 LinuxCNC's rs274 (linuxcnc-uspace)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
preset="${1:-release}"

packages=(build-essential cmake ninja-build qtbase5-dev libvtk9-dev libvtk9-qt-dev
          qttools5-dev qttools5-dev-tools libeigen3-dev libgtest-dev libgmock-dev
          libbenchmark-dev xvfb xauth python3 locales)
# fuzzing (libFuzzer), lint (clang-tidy, clang-query) and memcheck: not
# needed by the build or the suite (docs/FUZZING.md, docs/DECISIONS.md)
tools=(clang clang-tidy clang-tools valgrind)
case "$preset" in
  fuzz) packages+=(clang) ;;
  tools) packages+=("${tools[@]}") ;;
  bench) packages+=(linuxcnc-uspace) ;;  # rs274 -g, issue 21's reference (docs/DECISIONS.md)
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing missing packages: ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The German desk's locale: the suite runs the CLI, the core and the panel
# under LC_ALL=de_DE.UTF-8 (decimal comma) to prove numbers stay '.' (D-013).
if ! locale -a 2>/dev/null | grep -qi '^de_DE\.utf-\?8$'; then
  echo "setup: generating the locale de_DE.UTF-8"
  if grep -q '^# *de_DE.UTF-8 UTF-8' /etc/locale.gen; then
    "${sudo_cmd[@]}" sed -i 's/^# *de_DE.UTF-8 UTF-8/de_DE.UTF-8 UTF-8/' /etc/locale.gen
  elif ! grep -q '^de_DE.UTF-8 UTF-8' /etc/locale.gen; then
    echo 'de_DE.UTF-8 UTF-8' | "${sudo_cmd[@]}" tee -a /etc/locale.gen >/dev/null
  fi
  "${sudo_cmd[@]}" locale-gen >/dev/null
fi

[ "$preset" = tools ] || [ "$preset" = bench ] && exit 0
cd "$here"
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset"
