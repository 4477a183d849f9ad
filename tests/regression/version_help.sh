#!/usr/bin/env bash
# -version and -help of every program (issue 33): -version prints the program, hylc's version and git
# revision and the PETSc, HDF5 and MPI versions it runs with (compared with pkg-config's), then ends;
# -help lists hylc's own options first and PETSc's after one header, and a list option shows every
# value of its default (and the given ones).
set -u
B=$HYLC_BIN
T=$HYLC_TMP
die() { echo "FAIL: $*"; exit 1; }
version=$(sed -n 's/^#define HYLC_VERSION_STRING "\(.*\)"/\1/p' "$HYLC_ROOT/include/hylc/sys.h")
[ -n "$version" ] || die "no HYLC_VERSION_STRING in include/hylc/sys.h"
petsc=$(pkg-config --modversion petsc 2>/dev/null)
hdf5=$(pkg-config --modversion hdf5-openmpi 2>/dev/null)
header='^PETSc options \(the solvers, logging, debugging'
for p in pattern solve sample fit eval calibrate; do
  # -version, also among other options: nothing else is done
  "$B/hylc-$p" -version -pattern_type plain -sampler_output "$T/never.h5" >"$T/v.txt" 2>&1 || { cat "$T/v.txt"; die "hylc-$p -version exits non-zero"; }
  [ "$(wc -l <"$T/v.txt")" -eq 4 ] || { cat "$T/v.txt"; die "hylc-$p -version: not 4 lines"; }
  grep -Eq "^hylc-$p $version \(git ([0-9a-f]{7,}(-dirty)?|unknown)\)\$" "$T/v.txt" || { cat "$T/v.txt"; die "hylc-$p -version: no line 'hylc-$p $version (git <revision>)'"; }
  [ -z "$petsc" ] || grep -q "^PETSc: $petsc," "$T/v.txt" || { cat "$T/v.txt"; die "hylc-$p -version: PETSc is not $petsc"; }
  [ -z "$hdf5" ] || grep -qx "HDF5: $hdf5" "$T/v.txt" || { cat "$T/v.txt"; die "hylc-$p -version: HDF5 is not $hdf5"; }
  grep -q '^MPI: ' "$T/v.txt" || die "hylc-$p -version: no MPI line"
  [ ! -e "$T/never.h5" ] || die "hylc-$p -version did work"

  # -help: hylc's options, then one header, then PETSc's
  "$B/hylc-$p" -help >"$T/h.txt" 2>&1 || { tail -n 5 "$T/h.txt"; die "hylc-$p -help exits non-zero"; }
  [ "$(grep -Ec "$header" "$T/h.txt")" -eq 1 ] || die "hylc-$p -help: not one PETSc header"
  hl=$(grep -En "$header" "$T/h.txt" | cut -d: -f1)
  first=$(grep -En '^  -[a-z]' "$T/h.txt" | head -n 1 | cut -d: -f1)
  [ "$first" -lt "$hl" ] && [ "$first" -le 25 ] || die "hylc-$p -help: the first option is on line $first (PETSc header on $hl)"
  ! head -n "$hl" "$T/h.txt" | grep -Eq '^(Options for all PETSc programs|Petsc Release Version|Nonlinear solver \(SNES\)|Krylov Method)' || die "hylc-$p -help: PETSc's sections before the header"
  tail -n +"$hl" "$T/h.txt" | grep -q '^Options for all PETSc programs' || die "hylc-$p -help: PETSc's general options missing after the header"
  # (an embedded PETSc solver's options, -calibrate_tao_* as -micro_snes_*, are PETSc's and belong after it)
  if tail -n +"$hl" "$T/h.txt" | grep -E '^  -(pattern|yarn|sampler|reference|fit|calibrate|solve|eval)_[a-z]' | grep -qv '^  -calibrate_tao_'; then
    tail -n +"$hl" "$T/h.txt" | grep -E '^  -(pattern|yarn|sampler|reference|fit|calibrate|solve|eval)_[a-z]' | grep -v '^  -calibrate_tao_' | head -n 3
    die "hylc-$p -help: hylc options after PETSc's header"
  fi
done
# every value of a list option
"$B/hylc-sample" -help >"$T/h.txt" 2>&1
grep -Eq '^  -sampler_range_sx <-0\.6,[0-9.]+>: ' "$T/h.txt" || { grep range_sx "$T/h.txt"; die "-sampler_range_sx does not show both values"; }
grep -Eq '^  -pattern_size <0,0>: ' "$T/h.txt" || { grep pattern_size "$T/h.txt"; die "-pattern_size does not show both values"; }
"$B/hylc-sample" -help -sampler_range_sx -0.1,0.2 >"$T/h.txt" 2>&1
grep -Eq '^  -sampler_range_sx <now -0\.1,0\.2 : formerly -0\.6,[0-9.]+>: ' "$T/h.txt" || { grep range_sx "$T/h.txt"; die "-sampler_range_sx does not show the given values"; }
"$B/hylc-solve" -help >"$T/h.txt" 2>&1
grep -Eq '^  -strain <0,0,0,0,0,0>: ' "$T/h.txt" || { grep -- '-strain ' "$T/h.txt"; die "-strain does not show six values"; }
grep -Eq '^  -solve_uniaxial_strains <0\.05,0\.1,0\.2>: ' "$T/h.txt" || { grep uniaxial_strains "$T/h.txt"; die "-solve_uniaxial_strains does not show its three defaults"; }
exit 0
