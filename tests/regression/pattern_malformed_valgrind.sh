#!/usr/bin/env bash
# The malformed-pattern cases under valgrind memcheck: no invalid reads/writes or uses of
# uninitialized memory on any error path.
HYLC_VALGRIND=1 exec bash "$(dirname "$0")/pattern_malformed.sh"
