#!/usr/bin/env bash
# Probe 4.8 (options files and values): a malformed YAML options file used to give PETSc's "YAML parser
# loading error" with neither file nor line, and a non-numeric value "Input string abc has no integer
# value" naming neither option nor file. Now one line naming the file, line, option and value (issue 33:
# any error about an option set in a file, values with blanks and nested YAML keys too). Since issue 33
# the file is parsed by libyaml (src/sys/yamlcheck.c), whose messages give line and column.
set -u
. "$(dirname "$0")/probe_common.inc"
cd "$HYLC_TMP"
P=$HYLC_BIN/hylc-pattern
printf 'pattern_type: plain\npattern_radius 1e-3\n' >nocolon.yaml
refused no-colon "^hylc: error: nocolon.yaml:2:1: while scanning a simple key: could not find expected ':' \(at line 3, column 1\)" $P -options_file nocolon.yaml
printf 'pattern_type: plain\n  pattern_radius: 1e-3\n' >indent.yaml
refused indentation "^hylc: error: indent.yaml:2:17: mapping values are not allowed in this context" $P -options_file indent.yaml
printf '# comment\npattern_type: "plain\n' >quote.yaml
refused unclosed-quote "^hylc: error: quote.yaml:2:15: while scanning a quoted scalar: found unexpected end of stream" $P -options_file quote.yaml
printf 'pattern_type: plain\n\tpattern_radius: 1e-3\n' >tab.yaml
refused tab "^hylc: error: tab.yaml:.*: found a tab character that violates indentation \(at line 2, column 1\)" $P -options_file tab.yaml
printf 'pattern_size: [4, 4\n' >bracket.yaml
refused unclosed-list "^hylc: error: bracket.yaml:1:15: while parsing a flow sequence: did not find expected ',' or '\]'" $P -options_file bracket.yaml
# the structure PETSc's reader takes: a top-level mapping, option names as keys, no key without a value
printf -- '- pattern_type\n- plain\n' >list.yaml
refused top-list "^hylc: error: list.yaml:1:1: the top level of an options file must be 'key: value' lines, found a list" $P -options_file list.yaml
printf 'pattern type: plain\n' >name.yaml
refused bad-name "^hylc: error: name.yaml:1:1: 'pattern type' is not an option name" $P -options_file name.yaml
printf 'pattern_type: plain\npattern_radius:\n' >empty.yaml
refused no-value "^hylc: error: empty.yaml:2:16: 'pattern_radius' has no value" $P -options_file empty.yaml
refused missing-file "^hylc: error: Cannot open options file nonexistent.yaml: No such file" $P -options_file nonexistent.yaml
mkdir -p adir.yaml
refused directory "^hylc: error: Cannot read options file adir.yaml: it is a directory" $P -options_file adir.yaml
# values that are not numbers: the option and the file line that set it are named
printf 'pattern_type: plain\n# the sampling plan\nsampler_n1: abc\n' >n1.yaml
refused yaml-integer "^hylc: error: n1.yaml:3: option -sampler_n1: 'abc' is not an integer$" "$HYLC_BIN/hylc-sample" -options_file n1.yaml -sampler_output s.h5
refused cmdline-real "^hylc: error: option -strain: 'a' is not a number$" "$HYLC_BIN/hylc-solve" -pattern_type plain -strain a,0,0,0,0,0
refused cmdline-int "^hylc: error: option -pattern_size: 'x' is not an integer$" $P -pattern_type plain -pattern_size x,4
# issue 33: a value with a unit, a nested key, a finite-number check, a range check, a bad choice, a
# plain options file, the last of two files: each names the file, the line and the option
printf 'pattern_type: plain\nyarn_E: 1e6 Pa\n' >unit.yaml
refused yaml-unit "^hylc: error: unit.yaml:2: option -yarn_E: '1e6 Pa' is not a number$" "$HYLC_BIN/hylc-solve" -options_file unit.yaml -strain 0,0,0,0,0,0
printf 'pattern_type: plain\nmicro:\n  # the Newton solver\n  rtol: abc\n' >nested.yaml
refused yaml-nested "^hylc: error: nested.yaml:4: option -micro_rtol: 'abc' is not a number$" "$HYLC_BIN/hylc-solve" -options_file nested.yaml -strain 0,0,0,0,0,0
printf 'pattern_type: plain\n\nyarn_E: inf\n' >inf.yaml
refused yaml-finite "^hylc: error: inf.yaml:3: Option -yarn_E inf: not a finite number$" "$HYLC_BIN/hylc-solve" -options_file inf.yaml -strain 0,0,0,0,0,0
printf 'pattern_type: plain\nyarn_E: -5\n' >neg.yaml
refused yaml-check "^hylc: error: neg.yaml:2: -yarn_E must be positive" "$HYLC_BIN/hylc-solve" -options_file neg.yaml -strain 0,0,0,0,0,0
printf 'pattern_type: plain\nsampler_family: silk\n' >family.yaml
refused yaml-choice "^hylc: error: family.yaml:2: Unknown option silk for -sampler_family" "$HYLC_BIN/hylc-sample" -options_file family.yaml -sampler_output s.h5
printf -- '-pattern_type plain\n\n-yarn_kc 5x\n' >plain.txt
refused plain-file "^hylc: error: plain.txt:3: option -yarn_kc: '5x' is not a number$" "$HYLC_BIN/hylc-solve" -options_file plain.txt -strain 0,0,0,0,0,0
printf 'yarn_kc: 5\n' >first.yaml
printf '# second\nyarn_kc: 5 N/m\n' >second.yaml
refused last-file "^hylc: error: second.yaml:2: option -yarn_kc: '5 N/m' is not a number$" "$HYLC_BIN/hylc-solve" -pattern_type plain -options_file first.yaml -options_file second.yaml -strain 0,0,0,0,0,0
refused cmdline-wins "^hylc: error: option -yarn_kc: '7x' is not a number$" "$HYLC_BIN/hylc-solve" -pattern_type plain -options_file first.yaml -yarn_kc 7x -strain 0,0,0,0,0,0
# a well-formed file with comments, blank lines and a block still loads
printf -- '---\n# a comment\npattern_type: plain   # trailing comment\n\npattern_radius: 1.0e-3\n' >good.yaml
$P -options_file good.yaml >good.txt 2>&1 || { cat good.txt; echo "FAIL: a well-formed YAML file is refused"; exit 1; }
grep -q 'type: plain' good.txt || { cat good.txt; echo "FAIL: good.yaml not applied"; exit 1; }
# a block list, and a list written over two lines, are YAML that PETSc reads: accepted
printf 'pattern_type: plain\npattern_size:\n  - 4\n  - 2\n' >blocklist.yaml
$P -options_file blocklist.yaml >bl.txt 2>&1 || { cat bl.txt; echo "FAIL: a block list is refused"; exit 1; }
printf 'pattern_type: plain\npattern_size: [4,\n  2]\n' >flowlist.yaml
$P -options_file flowlist.yaml >fl.txt 2>&1 || { cat fl.txt; echo "FAIL: a list over two lines is refused"; exit 1; }
cmp -s bl.txt fl.txt || { diff bl.txt fl.txt; echo "FAIL: the two spellings of one list differ"; exit 1; }
finish
