#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the Debian 12 packages FiveBar Studio needs, only those that are missing.
# Quiet when nothing is missing. Needs root (or sudo) when something is.
set -euo pipefail
packages=(
  cmake ninja-build g++ make pkg-config ccache
  libeigen3-dev nlohmann-json3-dev zlib1g-dev libnlopt-cxx-dev
  qt6-base-dev qt6-svg-dev qt6-serialport-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
  qt6-translations-l10n
  libgl-dev libgtest-dev libgmock-dev libbenchmark-dev
  hershey-fonts-data
  xvfb xauth
  dpkg-dev desktop-file-utils appstream man-db lintian
)
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "Installing missing packages: ${missing[*]}" >&2
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq >/dev/null
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
