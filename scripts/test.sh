#!/usr/bin/env bash
# Installs what is missing, builds everything, and runs every test (ctest).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
scripts/build.sh
export QT_QPA_PLATFORM=offscreen
ctest --preset release -j"$(nproc)"
