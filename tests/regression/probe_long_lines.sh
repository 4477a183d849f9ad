#!/usr/bin/env bash
# Issue 28, item 5: fixed fgets buffers (hylc-eval 4096, the calibration's data.txt 4096 and CSV 8192)
# split a long line and read its tail as data: a comment of 4,095 characters ending in "0.1 0 0 0 0 0"
# became a second strain of hylc-eval; an 8,191-character CSV comment ending in "0.3,0,0,0,0,0,500"
# became a calibration sample with Psi = 500. An empty CSV field ("0,,0,...") shifted the columns
# silently in hylc-eval's text input. Now lines of any length are one line (comments of 4 095, 8 191 and
# 100 000 characters, a data row padded to 10 000 characters), and an empty field is refused naming the
# file, line and column. The same for the fit's data.txt.
set -u
cd "$HYLC_TMP"
. "$HYLC_ROOT/tests/regression/probe_common.inc" || exit 1
die() { echo "FAIL: $*"; exit 1; }
B=$HYLC_BIN
comment() { # total-characters tail: a '#' comment of that many characters before its tail
  printf '#'
  head -c $(($1 - 1)) /dev/zero | tr '\0' x
  printf '%s\n' "$2"
}
printf '{"density": 0.3, "strain scale": [1, 1, 1, 100, 100], "coeffs": {"const": 0.5, "1D": [{"k": 0, "t": [-1, 0, 1], "p": [1, 0, 1], "m": [-1, 0, 1]}], "2D": []}}\n' >m.json
for n in 4095 4096 8191 100000; do
  { comment $n '0.1 0 0 0 0 0'; printf '0.2 0 0 0 0 0\n'; } >long$n.txt
  "$B/hylc-eval" -material m.json -eval_input long$n.txt -eval_output o$n.txt >e.txt 2>&1 || { cat e.txt; die "hylc-eval long$n.txt failed"; }
  grep -q '^evaluated 1 strains from' e.txt || { cat e.txt; die "long$n.txt: the comment's tail was read as a strain"; }
  [ "$(grep -vc '^#' o$n.txt)" = 1 ] && [ "$(grep -v '^#' o$n.txt)" = 0.57200000000000006 ] || { cat o$n.txt; die "long$n.txt: expected psi(0.2) = 0.572 only"; }
done
# a row padded with blanks to 10 000 characters is one row
{ printf '0.2'; head -c 10000 /dev/zero | tr '\0' ' '; printf '0 0 0 0 0\n'; } >pad.txt
"$B/hylc-eval" -material m.json -eval_input pad.txt -eval_output pad.out >e.txt 2>&1 && grep -q '^evaluated 1 strains' e.txt || { cat e.txt; die "pad.txt"; }
printf '0,,0,0,0,0\n' >empty.txt
expect_fail '^hylc: error: empty.txt:1: column 2 \(sa\): empty field$' "$B/hylc-eval" -material m.json -eval_input empty.txt -eval_output x.txt
printf '0,0,0,0,0,0,\n' >trail.txt
expect_fail '^hylc: error: trail.txt:1: 7 fields, expected 6 \(sx sa sy II00 II01 II11\)$' "$B/hylc-eval" -material m.json -eval_input trail.txt -eval_output x.txt
[ -e x.txt ] && die "x.txt written by a refused run"
# the calibration: an 8,191-character CSV comment ending in a row with Psi = 500 is no sample
for n in 8191 8192 20000; do
  { printf 'sx,sa,sy,II00,II01,II11,psi\n0,0,0,0,0,0,1\n'; comment $n '0.3,0,0,0,0,0,500'; printf '0.1,0,0,0,0,0,2\n'; } >c$n.csv
  "$B/hylc-calibrate" -pattern_type plain -calibrate_reference none -calibrate_target c$n.csv -calibrate_max_it 0 -calibrate_view >c.txt 2>&1 || { cat c.txt; die "c$n.csv failed"; }
  grep -q "target c$n.csv (csv), 2 samples" c.txt || { grep 'samples' c.txt; die "c$n.csv: the comment's tail was read as a sample"; }
  { comment $n '0.3 0 0 0 0 0 500'; printf '0 0 0 0 0 0 1\n0.1 0 0 0 0 0 2\n'; } >d$n.txt
  "$B/hylc-calibrate" -pattern_type plain -calibrate_reference none -calibrate_target d$n.txt -calibrate_max_it 0 -calibrate_view >c.txt 2>&1 || { cat c.txt; die "d$n.txt failed"; }
  grep -q "target d$n.txt (raw), 2 samples" c.txt || { grep 'samples' c.txt; die "d$n.txt: the comment's tail was read as a sample"; }
done
printf 'sx,sa,sy,II00,II01,II11,psi\n0,0,0,0,0,0,1\n0.1,,0,0,0,0,2\n' >e.csv
expect_fail '^hylc: error: e.csv:3: field 2: empty field$' "$B/hylc-calibrate" -pattern_type plain -calibrate_target e.csv
# the fit's data.txt: a long comment is no row (the row count decides the layout: 5 n1 + 9 n2^2)
mkdir -p raw
{ comment 9000 '0.5 0 0 0 0 0 1'; for t in 0 1 2 3 5; do for v in 0.1 0.2; do z=(0 0 0 0 0 0); z[$t]=$v; echo "${z[*]} $v"; done; done
  for p in "0 1" "0 2" "0 3" "0 5" "1 2" "1 3" "1 5" "2 3" "2 5"; do z=(0 0 0 0 0 0); set -- $p; z[$1]=0.1; z[$2]=0.1; echo "${z[*]} 0.02"; done; } >raw/data.txt
# (n1 = n2 = 1 does not fit: the message counts the rows, 19, not 20)
expect_fail '^hylc: error: raw/data.txt: 19 rows do not make 5 1D blocks of n1 = 1 rows' "$B/hylc-fit" -fit_input raw -fit_raw_n1 1 -fit_raw_n2 1 -fit_json f.json
finish
