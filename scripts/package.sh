#!/usr/bin/env bash
# Builds the release preset and a Debian package of it (CPack, DEB):
#   scripts/package.sh [OUTDIR]     (default: build/package)
# Install it with `sudo apt install ./mtc200-panel_<version>_<arch>.deb`.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$here/build/package}"
cd "$here"
cmake --preset release >/dev/null
cmake --build --preset release
mkdir -p "$out"
(cd build/release && cpack -G DEB -B "$out" >/dev/null)
rm -rf "$out/_CPack_Packages"
ls "$out"/*.deb
