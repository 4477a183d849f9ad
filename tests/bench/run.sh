#!/usr/bin/env bash
# Runs every benchmark in build/bench (make bench). Each prints its own measured figures.
set -u
cd "$(dirname "$0")/../.."
build=${BUILD:-build}
st=0
for exe in "$build"/bench/*; do
  [ -x "$exe" ] || continue
  echo "== $(basename "$exe")"
  "$exe" || st=1
done
exit $st
