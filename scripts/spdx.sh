#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# scripts/spdx.sh [--check] [SOURCE_DIR]: every project source file carries the licence's SPDX
# line (GPL-3.0-or-later, LICENSE) as its first line, or its second after a shebang:
#   // SPDX-License-Identifier: GPL-3.0-or-later     *.cpp *.hpp *.h
#   # SPDX-License-Identifier: GPL-3.0-or-later      CMakeLists.txt *.cmake *.sh *.py
# Without --check it adds the line where it is missing (idempotent); with --check it lists the
# files without it and exits 1 when there is any (ctest Package.SpdxHeaders). Test data (SVG,
# JSON, G-code, CSV, .ts) carries no header.
set -euo pipefail
check=0
if [ "${1:-}" = --check ]; then check=1; shift; fi
cd "${1:-$(dirname "$0")/..}"
spdx="SPDX-License-Identifier: GPL-3.0-or-later"
dirs=(app cmake core drivers fuzz i18n job paint resources scripts session tests translations widgets)

source_files() {
  echo CMakeLists.txt
  find "${dirs[@]}" -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \
    -o -name CMakeLists.txt -o -name '*.cmake' -o -name '*.sh' -o -name '*.py' \) | LC_ALL=C sort
}
comment_for() {
  case "$1" in
    *.cpp | *.hpp | *.h) echo "// $spdx" ;;
    *) echo "# $spdx" ;;
  esac
}

missing=0
while IFS= read -r f; do
  line=$(comment_for "$f")
  if head -n 2 "$f" | grep -qxF -- "$line"; then continue; fi
  if [ "$check" -eq 1 ]; then
    echo "no SPDX line: $f"
    missing=$((missing + 1))
    continue
  fi
  tmp=$(mktemp)
  if head -n 1 "$f" | grep -q '^#!'; then
    { head -n 1 "$f"; echo "$line"; tail -n +2 "$f"; } >"$tmp"
  else
    { echo "$line"; cat "$f"; } >"$tmp"
  fi
  cat "$tmp" >"$f"  # keeps the file's mode (executable scripts stay executable)
  rm -f "$tmp"
  echo "added: $f"
done < <(source_files)

if [ "$check" -eq 1 ]; then
  [ "$missing" -eq 0 ] || { echo "FAIL: $missing files without '$spdx' (scripts/spdx.sh adds it)"; exit 1; }
  echo "SPDX line in all $(source_files | wc -l) source files"
fi
