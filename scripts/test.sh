#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs what is missing, builds everything, and runs every test (ctest).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
scripts/build.sh
# The real GRBL 1.1h firmware as a host simulator, for tests/firmware and the replay test in
# tests/drivers (built once into ~/.cache/grbl-sim; those tests skip when ../shared is absent).
if [ -x ../shared/tools/grbl-sim/build.sh ]; then
  ../shared/tools/grbl-sim/build.sh >/dev/null ||
    echo "warning: the GRBL simulator did not build; the firmware tests will be skipped" >&2
fi
export QT_QPA_PLATFORM=offscreen
ctest --preset release -j"$(nproc)"
