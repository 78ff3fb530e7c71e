#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs what is missing, builds, and starts FiveBar Studio connected to the built-in
# simulated machine with the demo drawing loaded. Extra arguments go to the studio.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
scripts/build.sh
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  echo "No display found: starting the studio under xvfb-run (screenshots only)." >&2
  exec xvfb-run -a build/release/app/studio/fivebar-studio --demo "$@"
fi
exec build/release/app/studio/fivebar-studio --demo "$@"
