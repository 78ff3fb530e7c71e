#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Configures (once) and builds the release preset. Quiet unless something fails.
set -euo pipefail
cd "$(dirname "$0")/.."
# ccache (when installed) hashes paths below the clone relative to it: another clone hits the cache.
export CCACHE_BASEDIR="$PWD"
[ -f build/release/build.ninja ] || cmake --preset release >/tmp/fivebar-configure.log 2>&1 \
  || { cat /tmp/fivebar-configure.log >&2; exit 1; }
cmake --build --preset release -- -j"$(nproc)" >/tmp/fivebar-build.log 2>&1 \
  || { tail -n 60 /tmp/fivebar-build.log >&2; exit 1; }
