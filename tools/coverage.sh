#!/usr/bin/env bash
# Line coverage per stage (src/<stage>) of a COVERAGE=1 build after its tests ran (make coverage,
# docs/testing.md): gcov over the objects of $BUILD/obj/src (a source no test ran counts as 0 %); with
# lcov installed also $BUILD/coverage/lcov.info and an HTML report in $BUILD/coverage/html.
set -eu
cd "$(dirname "$0")/.."
build=${BUILD:-build-cov}
obj=$build/obj
[ -d "$obj/src" ] || { echo "coverage: no $obj/src: build with 'make COVERAGE=1' and run the tests first" >&2; exit 1; }
command -v gcov >/dev/null || { echo "coverage: gcov not found" >&2; exit 1; }

# gcov -n prints, per file of a translation unit, "File 'path'" then "Lines executed:P% of N"; only the
# stage's own sources count (not the headers they inline)
for dir in src/*/; do
  stage=$(basename "$dir")
  for c in "$dir"*.c; do
    [ -f "$obj/${c%.c}.gcno" ] || continue
    gcov -n -o "$obj/$dir" "$c" 2>/dev/null | awk -v stage="$stage" -v want="$c" '
      /^File / { f = $2; gsub("\047", "", f); next }
      /^Lines executed:/ && f == want { split($0, a, /[:% ]+/); printf "%s %d %d\n", stage, a[5], int(a[3] * a[5] / 100 + 0.5); f = "" }'
  done
done | awk '
  { n[$1] += $2; c[$1] += $3; N += $2; C += $3 }
  END {
    printf "%-10s %8s %8s %7s\n", "stage", "lines", "covered", "percent"
    for (s in n) printf "%-10s %8d %8d %6.1f%%\n", s, n[s], c[s], n[s] ? 100 * c[s] / n[s] : 0 | "sort"
    close("sort")
    printf "%-10s %8d %8d %6.1f%%\n", "total", N, C, N ? 100 * C / N : 0
    lo = ""
    for (s in n) if (n[s] && (lo == "" || c[s] / n[s] < c[lo] / n[lo])) lo = s
    if (lo != "") printf "least covered: %s (%.1f%%)\n", lo, 100 * c[lo] / n[lo]
  }'

if command -v lcov >/dev/null && command -v genhtml >/dev/null; then
  mkdir -p "$build/coverage"
  if lcov -q --capture --directory "$obj/src" --base-directory . --no-external --output-file "$build/coverage/lcov.info" >/dev/null 2>&1 &&
    genhtml -q --output-directory "$build/coverage/html" "$build/coverage/lcov.info" >/dev/null 2>&1; then
    echo "lcov report: $build/coverage/html/index.html"
  else
    echo "lcov failed (the gcov summary above stands)"
  fi
fi
