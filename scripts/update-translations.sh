#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Refreshes every translations/fivebar_LANG.ts from the sources (lupdate, through the build's
# update_translations target: new strings are added as unfinished, strings gone from the sources
# are dropped) and lists what is left to translate, per language. Exit 1 while anything is.
# Translate with Qt Linguist (`linguist translations/fivebar_fr.ts`) or by editing the XML:
# fill the <translation> and remove type="unfinished". The build compiles them (lrelease).
set -euo pipefail
cd "$(dirname "$0")/.."
[ -f build/release/build.ninja ] || cmake --preset release >/tmp/fivebar-configure.log 2>&1 \
  || { cat /tmp/fivebar-configure.log >&2; exit 1; }
cmake --build build/release --target update_translations >/tmp/fivebar-lupdate.log 2>&1 \
  || { tail -n 30 /tmp/fivebar-lupdate.log >&2; exit 1; }
status=0
for ts in translations/fivebar_*.ts; do
  lang=$(basename "$ts" .ts); lang=${lang#fivebar_}
  left=$(translations/unfinished.sh "$ts" || true)
  if [ -z "$left" ]; then
    echo "$lang: complete ($(grep -c '<message' "$ts") messages)"
  else
    echo "$lang: $(wc -l <<<"$left") unfinished:"
    sed 's/^/  /' <<<"$left"
    status=1
  fi
done
exit $status
