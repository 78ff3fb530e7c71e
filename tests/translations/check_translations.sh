#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# check_translations.sh LUPDATE PROJECT.cmake GenerateLUpdateProject.cmake SOURCE_DIR ALIASES
# ALIASES: lupdate's -tr-function-alias value (the core's FB_TR markers), as the build uses it.
set -uo pipefail
lupdate=$1 project=$2 generate=$3 source=$4 aliases=${5:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp "$source"/translations/fivebar_*.ts "$tmp/"
[ "$(ls "$tmp" | wc -l)" -ge 3 ] || { echo "FAIL: expected de, es and fr .ts files"; exit 1; }
cmake -DIN_FILE="$project" -DOUT_FILE="$tmp/project.json" -P "$generate" || { echo "FAIL: lupdate project"; exit 1; }
"$lupdate" -project "$tmp/project.json" -ts "$tmp"/fivebar_*.ts -no-obsolete -locations none \
  ${aliases:+-tr-function-alias "$aliases"} \
  >"$tmp/lupdate.log" 2>&1 || { cat "$tmp/lupdate.log"; echo "FAIL: lupdate"; exit 1; }
status=0
for ts in "$tmp"/fivebar_*.ts; do
  lang=$(basename "$ts" .ts)
  messages=$(grep -c '<message' "$ts")
  [ "$messages" -gt 100 ] || { echo "FAIL: $lang has only $messages messages"; status=1; }
  if ! left=$("$source/translations/unfinished.sh" "$ts"); then
    echo "FAIL: $lang: $(wc -l <<<"$left") messages unfinished or missing (scripts/update-translations.sh adds and lists them):"
    echo "$left"
    status=1
  else
    echo "$lang: $messages messages, all translated"
  fi
done
exit $status
