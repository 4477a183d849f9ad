#!/usr/bin/env bash
# Replays every input the fuzzers found (tests/fuzz/regressions/<harness>/) and the hand-written seeds
# (tests/fuzz/seeds/<harness>/) through the harness code built with gcc and a plain main
# (build/fuzz/<harness>, tests/fuzz/replay.c). Each input must be read or refused with an error return:
# no crash, no sanitizer report (the ASan build), no hang. Also checks that a refused input really was
# refused (the reader's message is suppressed in the harness, so this replays the pattern findings
# through hylc-pattern, which must exit non-zero with a one-line error naming the file).
set -u
cd "$HYLC_ROOT"
fz=$HYLC_BIN/../fuzz
fail=0
n=0
for h in fuzz_pyp fuzz_material_json fuzz_fit_raw fuzz_calibrate_target fuzz_eval_input fuzz_obj; do
  [ -x "$fz/$h" ] || { echo "missing $fz/$h (run make)"; exit 1; }
  files=()
  for f in tests/fuzz/regressions/$h/* tests/fuzz/seeds/$h/*; do [ -f "$f" ] && files+=("$f"); done
  [ ${#files[@]} -eq 0 ] && continue
  timeout 120 "$fz/$h" "${files[@]}" >"$HYLC_TMP/$h.log" 2>&1
  st=$?
  n=$((n + ${#files[@]}))
  if [ $st -ne 0 ] || grep -qE 'Sanitizer|runtime error:' "$HYLC_TMP/$h.log"; then
    echo "FAIL: $h (exit $st) on:"
    grep '^replay:' "$HYLC_TMP/$h.log" | tail -n 1
    grep -E 'ERROR|SUMMARY|runtime error' "$HYLC_TMP/$h.log" | head -n 5
    fail=1
  fi
done
# the pattern findings through the program: refused with one error line naming the file, not a signal
for f in tests/fuzz/regressions/fuzz_pyp/*; do
  [ -f "$f" ] || continue
  timeout 60 "$HYLC_BIN/hylc-pattern" -pattern_file "$f" >"$HYLC_TMP/out.txt" 2>&1
  st=$?
  if [ $st -eq 0 ] || [ $st -ge 124 ] || ! grep -q "hylc: error: .*$(basename "$f")" "$HYLC_TMP/out.txt"; then
    echo "FAIL: hylc-pattern -pattern_file $f: exit $st"; head -n 5 "$HYLC_TMP/out.txt"; fail=1
  fi
done
echo "$n inputs replayed"
exit $fail
