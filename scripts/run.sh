#!/usr/bin/env bash
# Sets up, builds (Release) and starts the panel on the built-in demo cell.
# Extra arguments pass through to mtc200-panel, e.g. --screen restart.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh" release
exec "$here/build/release/app/mtc200-panel" "$@"
