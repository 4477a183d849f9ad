#!/usr/bin/env bash
# A table written as measured cloth and read back (hylc-eval -eval_measured_json, docs/measured-cloth.md,
# "Export"): the paper's stock1 exported, its measured-cloth sheet against the table's own: the strip
# tension T along x and y within 10 % at s = 2, 5 and 10 % (measured: 6.6 % at most along x, 8.2 % along
# y); the bias printed, not bounded (the format's shear is a single coefficient per direction). The file
# is a valid measured-cloth JSON (the reader) with the table's density. Skips (77) without the paper's
# stock1 table.
set -u
cd "$HYLC_TMP"
ev=$HYLC_BIN/hylc-eval
die() { echo "FAIL: $*"; exit 1; }
t=$HYLC_REFDATA/materials/stock1.json
[ -f "$t" ] || { echo "SKIP: the paper's table $t is absent"; exit 77; }
$ev -material "$t" -eval_sheet -eval_sheet_json table.json -eval_measured_json s1mc.json >out.txt 2>&1 || { cat out.txt; die "export failed"; }
grep -Eq '^wrote s1mc.json \(measured cloth: strip tension error RMS [0-9.]+ %, largest [0-9.]+ % at 2-10 %.*rest moment of [0-9.e-]+ N m/m\)$' out.txt || { cat out.txt; die "the export line"; }
$ev -measured s1mc.json -eval_sheet -eval_sheet_json mc.json >mc.txt 2>&1 || { cat mc.txt; die "the exported file does not read back"; }
grep -q '^density: 0.331824 kg/m^2$' mc.txt || { cat mc.txt; die "density"; }
/usr/bin/python3 - <<'PY' || die "round trip"
import json
a = json.load(open("table.json")); b = json.load(open("mc.json"))
worst = {}
for d in ("x", "y", "bias"):
    for ra, rb in zip(a["tension"][d], b["tension"][d]):
        r = rb["T"] / ra["T"]
        print("%-4s s %.2f: table T %.6g N/m, exported %.6g N/m, ratio %.4f" % (d, ra["s"], ra["T"], rb["T"], r))
        worst[d] = max(worst.get(d, 0), abs(r - 1))
print("largest |ratio - 1|:", {k: round(v, 4) for k, v in worst.items()})
assert worst["x"] <= 0.10 and worst["y"] <= 0.10, "the round trip of stock1 should keep T within 10 % along x and y"
PY
echo "stock1 exported and read back: T within 10 % along x and y"
