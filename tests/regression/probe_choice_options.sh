#!/usr/bin/env bash
# Probe 4.8 (choices): a bad value of a choice option used to print a PETSc traceback. Now one line
# naming the option and the value.
set -u
. "$(dirname "$0")/probe_common.inc"
cd "$HYLC_TMP"
refused pattern-type "^hylc: error: Unknown option bogus for -pattern_type" "$HYLC_BIN/hylc-pattern" -pattern_type bogus
refused sampler-family "^hylc: error: Unknown option silk for -sampler_family" "$HYLC_BIN/hylc-sample" -pattern_type plain -sampler_family silk -sampler_output s.h5
refused snes-type "^hylc: error: .*SNES type bogus.*option -micro_snes_type bogus" "$HYLC_BIN/hylc-solve" -pattern_type plain -strain 0,0,0,0,0,0 -micro_snes_type bogus
refused alpha-schedule "^hylc: error: -micro_alpha_schedule fast: must be paper, adaptive or hybrid" "$HYLC_BIN/hylc-solve" -pattern_type plain -strain 0,0,0,0,0,0 -micro_alpha_schedule fast
refused alpha-factor "^hylc: error: -micro_alpha_factor 0.5: must be finite and greater than 1" "$HYLC_BIN/hylc-solve" -pattern_type plain -strain 0,0,0,0,0,0 -micro_alpha_schedule adaptive -micro_alpha_factor 0.5
[ -e s.h5 ] && { echo "FAIL: an output was written"; exit 1; }
finish
