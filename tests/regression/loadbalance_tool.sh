#!/usr/bin/env bash
# tools/loadbalance.py (issue 15): a thinned plan of a generated plain weave (n1 6, n2 2) projected to
# n1 12, n2 4: the unit counts follow the plan (1 + 5 x 12 + 9 x 16 samples; 1 + 5 x 2 + 9 x 4 x 2
# half-lines), the projected total is the measured one times the replication, and the efficiencies and the
# largest units are consistent (1 rank: 100 %; never above 100 %). Skips (77) without h5py.
set -u
cd "$HYLC_TMP"
root=$HYLC_BIN/../..
die() { echo "FAIL: $*"; exit 1; }
/usr/bin/python3 -c 'import h5py, numpy' 2>/dev/null || { echo "python3-h5py / numpy not installed"; exit 77; }
$HYLC_BIN/hylc-sample -pattern_type plain -yarn_kc 50 -sampler_n1 6 -sampler_n2 2 -sampler_output s.h5 >run.txt 2>&1 || { cat run.txt; die "hylc-sample failed"; }
/usr/bin/python3 "$root/tools/loadbalance.py" s.h5 --n1 12 --n2 4 --ranks 1,2,7 >lb.txt 2>&1 || { cat lb.txt; die "loadbalance.py failed"; }
cat lb.txt
grep -q ' 205 cold units (batch 1), 83 half-lines' lb.txt || die "unit counts: expected 205 samples and 83 half-lines"
measured=$(sed -n 's/.*samples, \([0-9.]*\) s,.*/\1/p' lb.txt)
/usr/bin/python3 - "$measured" <<'PY' || die "projected total or efficiencies inconsistent"
import sys, re, h5py
t = h5py.File('s.h5', 'r')['samples']
time, term = t['time'][:], t['term'][:]
w = [1 if k == 0 else 2 if k <= 5 else 4 for k in term]
expect = sum(a * b for a, b in zip(time, w))
txt = open('lb.txt').read()
total = float(re.search(r'projected total: ([0-9.]+) CPU-s', txt).group(1))
assert abs(total - expect) <= 0.5 + 1e-3 * expect, (total, expect)
rows = re.findall(r'^\s+(\d+) \|\s+([0-9.]+)\s+([0-9.]+)% \|\s+([0-9.]+)\s+([0-9.]+)% \|\s+([0-9.]+)\s+([0-9.]+)%', txt, re.M)
assert [r[0] for r in rows] == ['1', '2', '7'], rows
for r in rows:
    for e in (r[2], r[4], r[6]):
        assert 0 < float(e) <= 100.0, r
assert all(float(x) == 100.0 for x in rows[0][2::2]), rows[0]
PY
exit 0
