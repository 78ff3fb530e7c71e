#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# check_package.sh BUILD_DIR VERSION SOURCE_DIR: builds the .deb with CPack from BUILD_DIR (already
# built) into a temporary directory and checks it: file name and control fields (dependencies
# computed by dpkg-shlibdeps, the extended Description's format), the installed files, the
# copyright file and the changelog, lintian (when installed: no error; warnings printed), the
# desktop entry (desktop-file-validate), the AppStream metainfo (appstreamcli validate --pedantic,
# its screenshots in docs/), the man pages (compressed, no groff warnings, every command and
# option of each --help described), and runs the packaged executables from the extracted tree:
# the versions, the presets, a plan of the packaged demo drawing, the studio's --help without a
# display. Prints every failure and exits 1 when there is any.
set -uo pipefail
build=$1 version=$2 source=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

arch=$(dpkg --print-architecture)
if ! cpack --config "$build/CPackConfig.cmake" -B "$tmp/out" >"$tmp/cpack.log" 2>&1; then
  tail -n 40 "$tmp/cpack.log"; echo "FAIL: cpack"; exit 1
fi
deb="$tmp/out/fivebar-studio_${version}_${arch}.deb"
[ -f "$deb" ] || { ls "$tmp/out"; echo "FAIL: no $deb"; exit 1; }
echo "built $(basename "$deb") ($(du -k "$deb" | cut -f1) kB)"

# Control fields: name, version, and the dependencies dpkg-shlibdeps found.
[ "$(dpkg-deb -f "$deb" Package)" = fivebar-studio ] || fail "Package field"
[ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || fail "Version field: $(dpkg-deb -f "$deb" Version)"
depends=$(dpkg-deb -f "$deb" Depends)
for lib in libc6 libstdc++6 libqt6widgets6 libqt6svg6 libqt6serialport6 libnlopt0 qt6-qpa-plugins hershey-fonts-data; do
  grep -q "\b$lib\b" <<<"$depends" || fail "Depends lacks $lib: $depends"
done
# The Description: a synopsis, then the extended lines in Debian's format (each starts with a
# space, " ." for an empty one, at most 80 characters; no ';' from a CMake list at their start).
dpkg-deb -f "$deb" Description >"$tmp/description.txt"
[ "$(wc -l <"$tmp/description.txt")" -ge 3 ] || fail "Description has no extended lines"
head -n 1 "$tmp/description.txt" | grep -qiE '^fivebar[- ]studio' && fail "the synopsis starts with the package name"
tail -n +2 "$tmp/description.txt" | awk -v f="$tmp/description-bad.txt" '
  !/^ [^ ]/ || /^ ;/ || length($0) > 80 { print "  line " NR + 1 ": [" $0 "]" >> f }'
[ -s "$tmp/description-bad.txt" ] && { cat "$tmp/description-bad.txt"; fail "extended Description lines not in Debian format"; }

root="$tmp/root"
dpkg-deb -x "$deb" "$root"
share="$root/usr/share"
for f in usr/bin/fivebar usr/bin/fivebar-studio usr/bin/fivebar-sim \
         usr/libexec/fivebar-studio/fivebar-svg-worker \
         usr/share/applications/fivebar-studio.desktop \
         usr/share/metainfo/io.github.fivebar.studio.metainfo.xml \
         usr/share/icons/hicolor/scalable/apps/fivebar-studio.svg \
         usr/share/man/man1/fivebar.1.gz usr/share/man/man1/fivebar-studio.1.gz usr/share/man/man1/fivebar-sim.1.gz \
         usr/share/doc/fivebar-studio/copyright usr/share/doc/fivebar-studio/changelog.gz \
         usr/share/doc/fivebar-studio/docs/first-job.md usr/share/doc/fivebar-studio/docs/studio.md \
         usr/share/fivebar-studio/demo/fivebar-demo.svg; do
  [ -s "$root/$f" ] || fail "missing $f"
done
for size in 16 22 24 32 48 64 128 256; do
  png="$share/icons/hicolor/${size}x${size}/apps/fivebar-studio.png"
  # PNG header: width and height are the big-endian words at bytes 16 and 20.
  dims=$(od -An -tu1 -j16 -N8 "$png" 2>/dev/null | awk '{print $3*256+$4 "x" $7*256+$8}')
  [ "$dims" = "${size}x${size}" ] || fail "icon ${size}x${size}: got '$dims'"
done
for ts in "$source"/translations/fivebar_*.ts; do
  lang=$(basename "$ts" .ts)
  [ -s "$share/fivebar-studio/translations/$lang.qm" ] || fail "missing translation $lang.qm"
done
# Nothing but /usr (no build tree paths, no stray headers or static libraries).
stray=$(cd "$root" && find . -type f ! -path './usr/*'; cd "$root" && find . -name '*.a' -o -name '*.h' -o -name '*.hpp')
[ -z "$stray" ] || fail "unexpected files: $stray"

# Compressed as policy wants: gzip -9 with no name and no time stamp in the header (bytes 4-7).
for gz in "$share"/man/man1/*.gz "$share/doc/fivebar-studio/changelog.gz"; do
  gzip -t "$gz" 2>/dev/null || { fail "not gzip: $gz"; continue; }
  [ "$(od -An -tu1 -j3 -N5 "$gz" | tr -s ' ')" = " 0 0 0 0 0" ] || fail "gzip header has a name or time: $gz"
done
[ -z "$(find "$share/man" -type f ! -name '*.gz')" ] || fail "uncompressed man pages: $(find "$share/man" -type f ! -name '*.gz')"
# The copyright file is machine-readable (DEP-5), the licence GPL-3+ pointing at common-licenses.
copyright="$share/doc/fivebar-studio/copyright"
head -n 1 "$copyright" | grep -qx 'Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/' \
  || fail "copyright: no DEP-5 Format line"
grep -qx 'License: GPL-3+' "$copyright" || fail "copyright: no License: GPL-3+"
grep -qF '/usr/share/common-licenses/GPL-3' "$copyright" || fail "copyright: no pointer to common-licenses/GPL-3"
# The changelog parses, and its version is the package's.
changelog_version=$(zcat "$share/doc/fivebar-studio/changelog.gz" | dpkg-parsechangelog -l - -S Version 2>&1)
[ "$changelog_version" = "$version" ] || fail "changelog version: $changelog_version"

# lintian (Debian package lintian, scripts/deps.sh): no error; warnings and infos are printed
# (docs/packaging.md says which ones are kept and why).
if command -v lintian >/dev/null; then
  lintian --fail-on error --tag-display-limit 0 --display-info "$deb" >"$tmp/lintian.log" 2>&1
  lintian_rc=$?
  grep -vE '^E: ' "$tmp/lintian.log" | sed 's/^/lintian: /'
  if [ "$lintian_rc" -ne 0 ] || grep -qE '^E: ' "$tmp/lintian.log"; then
    grep -E '^E: ' "$tmp/lintian.log"
    fail "lintian (exit $lintian_rc): $(grep -cE '^E: ' "$tmp/lintian.log") errors"
  fi
  echo "lintian: $(grep -cE '^E: ' "$tmp/lintian.log") errors, $(grep -cE '^W: ' "$tmp/lintian.log") warnings"
else
  echo "lintian not installed: not run (scripts/deps.sh installs it)"
fi

desktop-file-validate "$share/applications/fivebar-studio.desktop" || fail "desktop-file-validate"
appstreamcli validate --pedantic --no-net "$share/metainfo/io.github.fivebar.studio.metainfo.xml" \
  >"$tmp/appstream.log" 2>&1 || { cat "$tmp/appstream.log"; fail "appstreamcli validate --pedantic"; }
grep -q "<release version=\"$version\"" "$share/metainfo/io.github.fivebar.studio.metainfo.xml" \
  || fail "metainfo release is not $version"
grep -q '<project_license>GPL-3.0-or-later</project_license>' "$share/metainfo/io.github.fivebar.studio.metainfo.xml" \
  || fail "metainfo: no project_license GPL-3.0-or-later"
# The screenshots' URLs name files of this repository (the validator runs without the network).
shots=$(grep -oE 'https://raw.githubusercontent.com/fivebar/studio/main/[^<]+' \
  "$share/metainfo/io.github.fivebar.studio.metainfo.xml" | sed 's|^https://raw.githubusercontent.com/fivebar/studio/main/||')
[ -n "$shots" ] || fail "metainfo: no screenshots"
for shot in $shots; do [ -s "$source/$shot" ] || fail "metainfo screenshot $shot is not in the repository"; done

bin="$root/usr/bin"
# The versions: one, from CMake.
[ "$("$bin/fivebar" --version)" = "fivebar $version" ] || fail "fivebar --version: $("$bin/fivebar" --version)"
[ "$("$bin/fivebar-sim" --version)" = "fivebar-sim $version" ] || fail "fivebar-sim --version"
# The studio's --help and --version without any display (no QApplication before parsing).
studio_version=$(env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM "$bin/fivebar-studio" --version 2>&1)
[ "$studio_version" = "FiveBar Studio $version" ] || fail "fivebar-studio --version: $studio_version"
env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM "$bin/fivebar-studio" --help >"$tmp/studio-help.txt" 2>&1 \
  || { cat "$tmp/studio-help.txt"; fail "fivebar-studio --help without a display"; }
# Translated help (French) from the packaged translations.
env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM "$bin/fivebar-studio" --lang fr --help >"$tmp/studio-help-fr.txt" 2>&1
if [ -s "$share/fivebar-studio/translations/fivebar_fr.qm" ]; then
  cmp -s "$tmp/studio-help.txt" "$tmp/studio-help-fr.txt" && fail "fivebar-studio --lang fr --help is not translated"
fi

# Man pages: clean for groff, and describe every command and option of the real --help.
for page in fivebar fivebar-studio fivebar-sim; do
  warnings=$(LC_ALL=C.UTF-8 MANWIDTH=80 man --warnings -l "$share/man/man1/$page.1.gz" 2>&1 >/dev/null)
  [ -z "$warnings" ] || fail "man $page: $warnings"
  # lexgrog finds the NAME section as mandb would
  lexgrog "$share/man/man1/$page.1.gz" >/dev/null 2>&1 || fail "man $page: no parsable NAME section"
  LC_ALL=C.UTF-8 MANWIDTH=200 man -l "$share/man/man1/$page.1.gz" 2>/dev/null | sed 's/\xe2\x80\x90/-/g' >"$tmp/$page.txt"
done
covers() {  # covers PAGE HELP_TEXT_FILE WHAT: every --option in the help is in the page
  for opt in $(grep -oE -- '(^|[^[:alnum:]-])--[a-z][a-z0-9-]*' "$2" | grep -oE -- '--[a-z][a-z0-9-]*' | sort -u); do
    grep -qF -- "$opt" "$tmp/$1.txt" || fail "man $1 does not describe $opt ($3)"
  done
}
covers fivebar-studio "$tmp/studio-help.txt" "fivebar-studio --help"
"$bin/fivebar-sim" --help >"$tmp/sim-help.txt" 2>&1
covers fivebar-sim "$tmp/sim-help.txt" "fivebar-sim --help"
"$bin/fivebar" --help >"$tmp/cli-help.txt" 2>&1
for cmd in $(awk '/^commands:/{on=1; next} on && /^  [a-z]/{print $1}' "$tmp/cli-help.txt"); do
  grep -qE "^ *$cmd( |$)" "$tmp/fivebar.txt" || fail "man fivebar does not describe the command $cmd"
  "$bin/fivebar" "$cmd" --help >"$tmp/cli-$cmd.txt" 2>&1
  covers fivebar "$tmp/cli-$cmd.txt" "fivebar $cmd --help"
done

# Presets: the installed files are exactly the built-in presets, each a valid profile.
listed=$("$bin/fivebar" profile list | sort | tr '\n' ' ')
installed=$(cd "$share/fivebar-studio/presets" && ls *.json | sed 's/\.json$//' | sort | tr '\n' ' ')
[ "$listed" = "$installed" ] || fail "presets: listed '$listed', installed '$installed'"
"$bin/fivebar" profile check "$share"/fivebar-studio/presets/*.json >"$tmp/check.txt" || { cat "$tmp/check.txt"; fail "profile check of the installed presets"; }

# A plan of the packaged demo drawing on the packaged preset file, from the extracted tree, with
# the packaged SVG worker (wrapped to leave a mark: the build tree's worker exists here too, and
# findSvgWorker would fall back to it).
worker="$root/usr/libexec/fivebar-studio/fivebar-svg-worker"
mv "$worker" "$worker.real"
printf '#!/bin/sh\ntouch "%s/worker-used"\nexec "%s.real" "$@"\n' "$tmp" "$worker" >"$worker"
chmod +x "$worker"
( cd "$tmp" && "$bin/fivebar" plan "$share/fivebar-studio/demo/fivebar-demo.svg" \
    --machine "$share/fivebar-studio/presets/maker-plotter.json" -o job.gcode --report report.json ) \
  >"$tmp/plan.log" 2>&1 || { cat "$tmp/plan.log"; fail "fivebar plan with the packaged demo and preset"; }
moves=$(grep -cE '^G1 X-?[0-9]+\.[0-9]+ Y-?[0-9]+\.[0-9]+' "$tmp/job.gcode" 2>/dev/null)
[ "${moves:-0}" -gt 100 ] || fail "the planned demo job has ${moves:-0} G1 moves with C-locale numbers"
[ -f "$tmp/worker-used" ] || fail "fivebar plan did not run the packaged fivebar-svg-worker"

# `cmake --install` to another prefix: the same programs run from there and find their data
# (translations, presets) beside them, with no build tree around.
prefix="$tmp/prefix/opt/fivebar"
if cmake --install "$build" --prefix "$prefix" >"$tmp/install.log" 2>&1; then
  [ "$("$prefix/bin/fivebar" --version)" = "fivebar $version" ] || fail "installed to a prefix: fivebar --version"
  [ -s "$prefix/share/fivebar-studio/translations/fivebar_fr.qm" ] || fail "installed to a prefix: no fivebar_fr.qm"
  [ -x "$prefix/libexec/fivebar-studio/fivebar-svg-worker" ] || fail "installed to a prefix: no fivebar-svg-worker"
  env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM "$prefix/bin/fivebar-studio" --lang fr --help \
    >"$tmp/prefix-help-fr.txt" 2>&1 || fail "installed to a prefix: fivebar-studio --help"
  env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM "$prefix/bin/fivebar-studio" --lang en --help \
    >"$tmp/prefix-help-en.txt" 2>&1
  cmp -s "$tmp/prefix-help-fr.txt" "$tmp/prefix-help-en.txt" && fail "installed to a prefix: the studio finds no French"
else
  tail -n 20 "$tmp/install.log"; fail "cmake --install --prefix $prefix"
fi

[ "$failures" -eq 0 ] && echo "package OK: $(basename "$deb")"
exit $((failures > 0))
