#!/usr/bin/env bash
# The malformed-material cases under valgrind memcheck: no invalid reads/writes or uses of
# uninitialized memory on any error path.
HYLC_VALGRIND=1 exec bash "$(dirname "$0")/material_malformed.sh"
