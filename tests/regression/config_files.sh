#!/usr/bin/env bash
# config/<pattern>.yaml: every per-pattern configuration loads with hylc-pattern -options_file (PETSc
# parses *.yaml option files as YAML) without a word on stderr (the options of the other stages, -yarn_*,
# -sampler_*, -micro_*, -periodic_*, are ignored as another program's: src/sys/programs.c), names its own
# paper pattern, and sets exactly the four material options yarn_E, yarn_Es, yarn_G, yarn_kc, numbers
# with G = E/2.5. A misspelt key is an error naming it. Run from the repository root, where the files'
# relative pattern paths resolve.
set -u
cd "$(dirname "$0")/../.."
tool=$HYLC_BIN/hylc-pattern
die() { echo "FAIL: $*"; exit 1; }
patterns="basket satin stockinette cartridge_belt_rib slip_stitch_honeycomb satin_small stockinette_small"
expected=$'yarn_E\nyarn_Es\nyarn_G\nyarn_kc'
if [ ! -d ../shared/refdata/patterns/hylc2020 ]; then
  echo "skipped: ../shared/refdata/patterns/hylc2020 not found (the configs point there)"
  exit 77
fi

# one config: loads silently, names the pattern, exactly the four yarn keys, numeric values, G = E/2.5
check() { # name file
  local name=$1 f=$2 out=$HYLC_TMP/$1.out err=$HYLC_TMP/$1.err
  $tool -options_file "$f" >"$out" 2>"$err" || { cat "$out" "$err"; echo "hylc-pattern failed on $f"; return 1; }
  grep -Eq '^ *vertices: [0-9]+$' "$out" || { cat "$out"; echo "$f: no vertices line"; return 1; }
  grep -Eq "^ *file: \.\./shared/refdata/patterns/hylc2020/$name\.pyp$" "$out" || { cat "$out"; echo "$f: does not load $name.pyp"; return 1; }
  [ ! -s "$err" ] || { echo "$f: unexpected output on stderr:"; cat "$err"; return 1; }
  local names
  names=$(sed -n 's/^\(yarn_[A-Za-z]*\):.*/\1/p' "$f" | sort)
  [ "$names" = "$expected" ] || { echo "$f: the yarn keys are"; echo "$names"; echo "expected"; echo "$expected"; return 1; }
  sed -n 's/^\(yarn_[A-Za-z]*\): *\([^ #]*\).*/\1 \2/p' "$f" | awk -v f="$f" '
    $2 !~ /^[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?$/ { print f ": " $1 " = " $2 " is not a plain positive number"; bad = 1 }
    { v[$1] = $2 + 0 }
    END {
      if (!bad && (v["yarn_G"] <= 0 || v["yarn_E"] <= 0 || (v["yarn_G"] * 2.5 / v["yarn_E"] - 1) ^ 2 > 1e-12)) { print f ": G = " v["yarn_G"] " is not E/2.5 (E = " v["yarn_E"] ")"; bad = 1 }
      exit bad
    }' || return 1
  return 0
}

for name in $patterns; do
  f=config/$name.yaml
  [ -f "$f" ] || die "missing $f"
  check "$name" "$f" || die "$f"
done
# no other config files that this test does not know about
for f in config/*.yaml; do
  n=$(basename "$f" .yaml)
  case $n in demo | generated-* | profile-*) continue ;; esac # generated patterns: tests/regression/demo_schema.sh and generated_configs below
  [[ " $patterns " == *" $n "* ]] || die "$f is not checked by this test"
done

# a profile (config/profile-*.yaml) is added after a pattern's file: together they load silently, and
# every key of the profile is an option of some stage (a misspelt one is refused by name)
for f in config/profile-*.yaml; do
  $tool -options_file config/satin.yaml -options_file "$f" >"$HYLC_TMP/prof.out" 2>"$HYLC_TMP/prof.err" || { cat "$HYLC_TMP/prof.out" "$HYLC_TMP/prof.err"; die "$f does not load after config/satin.yaml"; }
  [ ! -s "$HYLC_TMP/prof.err" ] || { cat "$HYLC_TMP/prof.err"; die "$f: unexpected output on stderr"; }
done
grep -q '^sampler_reference: none$' config/profile-paper.yaml || die "config/profile-paper.yaml does not keep the stored tile as given"
grep -q '^sampler_graded_sub: 1$' config/profile-quick.yaml || die "config/profile-quick.yaml does not thin the graded plan"

# the check catches a misspelt key
sed 's/^yarn_kc:/yarn_ck:/' config/satin.yaml >"$HYLC_TMP/typo.yaml"
check satin "$HYLC_TMP/typo.yaml" >"$HYLC_TMP/typo.log" 2>&1 && { cat "$HYLC_TMP/typo.log"; die "a misspelt key in a config was not caught"; }
grep -q "hylc: error: $HYLC_TMP/typo.yaml:$(grep -n '^yarn_ck:' "$HYLC_TMP/typo.yaml" | cut -d: -f1): Unknown option(s): -yarn_ck " "$HYLC_TMP/typo.log" || { cat "$HYLC_TMP/typo.log"; die "hylc-pattern does not refuse the misspelt key by name, file and line"; }
# the generated-pattern configs load and generate (hylc-pattern reads the pattern options; sampler_family is hylc-sample's)
for f in config/generated-*.yaml; do
  $tool -options_file "$f" >"$HYLC_TMP/gen.out" 2>"$HYLC_TMP/gen.err" || { cat "$HYLC_TMP/gen.out" "$HYLC_TMP/gen.err"; die "$f does not generate"; }
  grep -Eq '^ *vertices: [0-9]+$' "$HYLC_TMP/gen.out" || die "$f: no vertices line"
  [ ! -s "$HYLC_TMP/gen.err" ] || { cat "$HYLC_TMP/gen.err"; die "$f: unexpected output on stderr"; }
done
exit 0
