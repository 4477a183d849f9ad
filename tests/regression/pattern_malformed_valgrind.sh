#!/usr/bin/env bash
# The malformed-pattern cases under valgrind memcheck (--leak-check=full
# --errors-for-leak-kinds=definite): no invalid reads/writes, no uses of uninitialized memory and no
# definite leak on the error paths (one case per path of the reader; see pattern_malformed.sh).
HYLC_VALGRIND=1 exec bash "$(dirname "$0")/pattern_malformed.sh"
