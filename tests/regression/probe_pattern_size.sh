#!/usr/bin/env bash
# Probe 4.11: -pattern_size -4,4 silently gave the default size. Now every generator option is checked
# (sizes two integers from 1 to 1000; radius > 0; lengths >= 0; all finite), naming option and value.
set -u
. "$(dirname "$0")/probe_common.inc"
cd "$HYLC_TMP"
P=$HYLC_BIN/hylc-pattern
refused negative-size "^hylc: error: Option -pattern_size -4,4: sizes must be integers from 1 to 1000" $P -pattern_type plain -pattern_size -4,4
refused zero-size "^hylc: error: Option -pattern_size 0,4: sizes must be" $P -pattern_type twill -pattern_size 0,4
refused huge-size "^hylc: error: Option -pattern_size 100000,4: sizes must be" $P -pattern_type plain -pattern_size 100000,4
refused three-values "^hylc: error: Option -pattern_size 4,4,4: more than 2 values$" $P -pattern_type plain -pattern_size 4,4,4
refused one-value "^hylc: error: Option -pattern_size 4: needs two integers nx,ny" $P -pattern_type stockinette -pattern_size 4
refused negative-radius "^hylc: error: Option -pattern_radius -1e-3: must be positive" $P -pattern_type plain -pattern_radius -1e-3
refused inf-radius "^hylc: error: Option -pattern_radius inf: not a finite number" $P -pattern_type rib -pattern_radius inf
refused negative-gap "^hylc: error: Option -pattern_gap -0.1: must be positive, or 0 for the default" $P -pattern_type plain -pattern_gap -0.1
refused negative-wale "^hylc: error: Option -pattern_wale -1: must be positive" $P -pattern_type stockinette -pattern_wale -1
refused tiny-seglen "^hylc: error: The plain weave of size 2,2 with -pattern_seglen 1e-12 m would have" $P -pattern_type plain -pattern_seglen 1e-12
refused vtk-tiles "^hylc: error: -pattern_vtk_tiles 100000,100000: at most 1e6 tile copies" $P -pattern_type plain -pattern_vtk t.vtk -pattern_vtk_tiles 100000,100000
# a valid size is honoured
$P -pattern_type plain -pattern_size 4,6 >ok.txt 2>&1 || { cat ok.txt; exit 1; }
grep -q 'vertices: 192' ok.txt || { cat ok.txt; echo "FAIL: -pattern_size 4,6 not honoured"; exit 1; }
finish
