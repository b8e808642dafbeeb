#!/bin/sh
# Tests of the piglit runner with a fake piglit (no GL, a few seconds); ends 'N passed, N failed'.
exec python3 "$(dirname "$0")/test_runner.py" "$@"
