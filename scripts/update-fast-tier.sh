#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Rewrites tests/slow_tests.txt from the test costs ctest measured in the last runs
# (build/release/Testing/Temporary/CTestCostData.txt): every test of the fast-tier binaries that
# took 0.5 s or more on average (the tier runs in well under a minute on 2 cores). The rest of those binaries is the fast tier, `ctest -L fast`.
# Run it after a whole-suite run when tests were added or changed speed.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build/release
[ -f "$build/Testing/Temporary/CTestCostData.txt" ] || { echo "run the suite first (ctest in $build)" >&2; exit 1; }
(cd "$build" && ctest --show-only=json-v1) > /tmp/fivebar-tests.json
python3 - "$build/Testing/Temporary/CTestCostData.txt" /tmp/fivebar-tests.json > tests/slow_tests.txt <<'PY'
import json, sys
costs = {}
for line in open(sys.argv[1]):
    p = line.split()
    if len(p) == 3:
        costs[p[0]] = float(p[2])
print("# Tests of the fast-tier binaries measured at 0.5 s or more (scripts/update-fast-tier.sh):")
print("# labelled slow instead of fast. One per line: BINARY TEST")
rows = []
for t in json.load(open(sys.argv[2]))["tests"]:
    cmd = t.get("command") or [""]
    binary = cmd[0].rsplit("/", 1)[-1]
    if costs.get(t["name"], 0.0) >= 0.5:
        rows.append(f"{binary} {t['name']}")
print("\n".join(sorted(rows)))
PY
echo "tests/slow_tests.txt: $(grep -vc '^#' tests/slow_tests.txt) slow tests"
