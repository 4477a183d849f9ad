#!/usr/bin/env bash
# The malformed-material cases under valgrind memcheck (--leak-check=full
# --errors-for-leak-kinds=definite): no invalid reads/writes, no uses of uninitialized memory and no
# definite leak on any error path (issue 12, probe 4.12).
HYLC_VALGRIND=1 exec bash "$(dirname "$0")/material_malformed.sh"
