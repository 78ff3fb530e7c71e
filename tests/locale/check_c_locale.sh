#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# check_c_locale.sh FIVEBAR FIVEBAR_STUDIO SOURCE_DIR: files and CLI output keep the decimal point
# in a German environment. Builds the de_DE.UTF-8 locale into a temporary LOCPATH (localedef,
# Debian package locales) and compares, byte for byte, what runs under LC_ALL=de_DE.UTF-8 and
# LC_ALL=C produce: `fivebar plan` (G-code, report, messages), `fivebar profile show`, the studio's
# headless --export-gcode, and `fivebar workspace --json`. Exit 77 (skipped) without localedef.
set -uo pipefail
cli=$1 studio=$2 source=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
command -v localedef >/dev/null && [ -f /usr/share/i18n/locales/de_DE ] || { echo "no localedef/de_DE sources: skipped"; exit 77; }
mkdir -p "$tmp/loc"
localedef -i de_DE -f UTF-8 "$tmp/loc/de_DE.UTF-8" >/dev/null 2>&1 || { echo "localedef failed: skipped"; exit 77; }
# Sanity: the German locale really has a decimal comma here (else the comparison proves nothing).
point=$(LOCPATH="$tmp/loc" LC_ALL=de_DE.UTF-8 locale decimal_point 2>/dev/null)
[ "$point" = "," ] || { echo "FAIL: de_DE.UTF-8 from LOCPATH has decimal point '$point'"; exit 1; }

demo="$source/resources/demo/fivebar-demo.svg"
run() {  # run LOCALE OUTDIR
  mkdir -p "$2"
  (cd "$2" && export LOCPATH="$tmp/loc" LC_ALL=$1 QT_QPA_PLATFORM=offscreen 2>/dev/null
   "$cli" plan "$demo" --machine maker-plotter -o job.gcode --report report.json --fill hatch >plan.out 2>plan.err
   "$cli" plan "$demo" --machine article5r -o tiny.gcode >infeasible.out 2>infeasible.err
   "$cli" profile show maker-plotter >profile.json 2>&1
   "$cli" workspace --machine maker-plotter --cells 64 --json ws.json >ws.out 2>&1
   "$studio" "$demo" --machine maker-plotter --export-gcode studio.gcode >studio.out 2>studio.err
   true)
}
run C "$tmp/c"
run de_DE.UTF-8 "$tmp/de"
# Wall-clock times differ from run to run: not part of the comparison.
sed -i -E 's/planned in [0-9]+ ms/planned in N ms/' "$tmp"/c/*.out "$tmp"/de/*.out
status=0
for f in job.gcode report.json plan.out plan.err infeasible.out infeasible.err profile.json ws.json ws.out studio.gcode studio.out studio.err; do
  if ! cmp -s "$tmp/c/$f" "$tmp/de/$f"; then
    echo "FAIL: $f differs under de_DE.UTF-8:"; diff "$tmp/c/$f" "$tmp/de/$f" | head -5; status=1
  fi
done
[ -s "$tmp/c/job.gcode" ] && [ -s "$tmp/c/studio.gcode" ] || { echo "FAIL: no G-code written"; status=1; }
[ -s "$tmp/c/infeasible.err" ] || [ -s "$tmp/c/infeasible.out" ] || { echo "FAIL: the infeasible plan printed nothing"; status=1; }
[ $status -eq 0 ] && echo "C locale kept: $(wc -l <"$tmp/c/job.gcode") G-code lines identical under de_DE.UTF-8"
exit $status
