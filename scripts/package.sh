#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs what is missing, builds the release, and writes the Debian package
# build/package/fivebar-studio_VERSION_ARCH.deb (CPack; dependencies by dpkg-shlibdeps).
# Install it with: sudo apt install ./build/package/fivebar-studio_*.deb
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
scripts/build.sh
cpack --config build/release/CPackConfig.cmake -B build/package >/tmp/fivebar-package.log 2>&1 \
  || { tail -n 40 /tmp/fivebar-package.log >&2; exit 1; }
rm -rf build/package/_CPack_Packages
ls build/package/fivebar-studio_*.deb
