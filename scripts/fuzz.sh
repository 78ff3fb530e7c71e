#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Fuzzes every parser a user's file or a board's bytes reach (fuzz/, docs/reliability.md):
# builds the fuzz preset (clang + libFuzzer, ASan + UBSan; Debian's clang and libclang-rt-14-dev,
# installed when missing), then runs each harness for SECONDS or 10 M executions, whichever
# comes first, from its seeds and the corpus it grew before (build/fuzz/corpus/NAME).
# Findings (crash-*, leak-*, timeout-*, oom-*) land in build/fuzz/findings/NAME; each run's log in
# build/fuzz/logs/NAME.log; a table of executions, coverage and findings is printed at the end.
# Usage: scripts/fuzz.sh [--seconds N] [--jobs J] [NAME...]   (default 600 s, 1 job, all harnesses)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=600 jobs=1 names=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    *) names+=("$1"); shift ;;
  esac
done
missing=()
for p in clang libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
export CCACHE_BASEDIR="$PWD"
[ -f build/fuzz/build.ninja ] || cmake --preset fuzz >build/fuzz-configure.log 2>&1 \
  || { cat build/fuzz-configure.log >&2; exit 1; }
cmake --build build/fuzz -- -j"$(nproc)" >build/fuzz-build.log 2>&1 || { tail -n 40 build/fuzz-build.log >&2; exit 1; }
all=$(sed -n 's/^fivebar_add_fuzzer(\([a-z_]*\) .*/\1/p' fuzz/CMakeLists.txt)
[ ${#names[@]} -gt 0 ] || mapfile -t names <<<"$all"
shared=../shared/corpus/svg
run_one() {
  local name=$1 seeds=() dict=""
  mkdir -p "build/fuzz/corpus/$name" "build/fuzz/findings/$name" build/fuzz/logs
  for d in "fuzz/seeds/$name" "fuzz/regressions/$name"; do [ -d "$d" ] && seeds+=("$d"); done
  case $name in
    svg_import) for d in resources/demo "$shared/resvg/valid" "$shared/resvg/adversarial" "$shared/vpype-plotter"; do
                  [ -d "$d" ] && seeds+=("$d"); done; dict=svg.dict ;;
    profile_json) seeds+=(tests/core/data); dict=json.dict ;;
    project|job_progress) dict=json.dict ;;
    path_data) dict=path.dict ;;
    gcode_job) dict=gcode.dict ;;
    grbl_response) dict=grbl.dict ;;
  esac
  local args=(-max_total_time="$seconds" -runs=10000000 -timeout=20 -rss_limit_mb=4096 -max_len=65536
              -print_final_stats=1 -artifact_prefix="build/fuzz/findings/$name/")
  [ -n "$dict" ] && args+=(-dict="fuzz/dict/$dict")
  ASAN_OPTIONS=detect_leaks=1 "build/fuzz/fuzz/fuzz_$name" "${args[@]}" "build/fuzz/corpus/$name" "${seeds[@]}" \
    >"build/fuzz/logs/$name.log" 2>&1 || true
}
export -f run_one; export seconds shared
printf '%s\n' "${names[@]}" | xargs -P "$jobs" -I{} bash -c 'run_one {}'
printf '%-16s %12s %8s %7s %7s %9s\n' harness executions seconds cov corpus findings
status=0
for name in "${names[@]}"; do
  log=build/fuzz/logs/$name.log
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  secs=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  corp=$(ls "build/fuzz/corpus/$name" | wc -l)
  found=$(ls "build/fuzz/findings/$name" | wc -l)
  grep -q 'ERROR: \(AddressSanitizer\|LeakSanitizer\|libFuzzer\)\|runtime error:\|fuzz check failed' "$log" && found=$((found > 0 ? found : 1))
  [ "$found" -eq 0 ] || status=1
  printf '%-16s %12s %8s %7s %7s %9s\n' "$name" "${runs:-?}" "${secs:-?}" "${cov:-?}" "$corp" "$found"
done
exit $status
