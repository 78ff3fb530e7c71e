#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Soak test (issue 28): a job of >= 20,000 G-code lines streamed by `fivebar stream` to the REAL
# GRBL 1.1h firmware (../shared/tools/grbl-sim) at a speed-up, with faults at seeded random times
# (unplug, host kill, power cut, soft reset, error:N, a board that stops answering), each recovered
# as a maker would; then the firmware's step traces are checked (every stroke drawn once, nothing
# lost). Not part of the default ctest (docs/reliability.md "Soak test").
# usage: scripts/soak.sh [--seed N] [--speedup 6] [--faults 12] [--lines 20000] [--out DIR] [--fivebar BIN]
# Exit 0 when every check passes, 1 otherwise (the report says which), 2 when something is missing.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
fivebar="$root/build/release/app/cli/fivebar"
shared="${FIVEBAR_SHARED_DIR:-$root/../shared}"
out=""
args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --fivebar) fivebar="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    *) args+=("$1"); shift ;;
  esac
done
start="$shared/tools/grbl-sim/start.sh"
[ -x "$fivebar" ] || { echo "soak: no fivebar at $fivebar (build it: scripts/build.sh, or --fivebar BIN)" >&2; exit 2; }
[ -f "$start" ] || { echo "soak: no grbl-sim at $start (set FIVEBAR_SHARED_DIR)" >&2; exit 2; }
sh "$shared/tools/grbl-sim/build.sh" >/dev/null || { echo "soak: cannot build grbl-sim" >&2; exit 2; }
[ -n "$out" ] || out=$(mktemp -d "${TMPDIR:-/tmp}/fivebar-soak.XXXXXX")
echo "soak: work folder $out"
exec python3 "$root/tests/soak/soak.py" --fivebar "$fivebar" --grbl-start "$start" --out "$out" ${args[@]+"${args[@]}"}
