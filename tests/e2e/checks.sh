# Sourced by the e2e check scripts (datapath-, jit-, threads-identity, llvm-start): the
# repository's paths, an empty output directory $build/NAME in $out, one line a check
# (pass, fail) and the closing tally (checks_end).  Usage (dash's '.' takes no arguments):
#   checks=NAME
#   . "$(dirname "$0")/checks.sh"
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${FP_BUILD_DIR:-$root/build/std}
out=$build/$checks
rm -rf "$out"
mkdir -p "$out"
passed=0 failed=0
pass() { passed=$((passed + 1)); echo "PASS $1"; }
fail() { failed=$((failed + 1)); echo "FAIL $1"; }
# "N passed, N failed" (the line ./fixpipe check counts); false on a failure
checks_end() { echo "$passed passed, $failed failed"; [ "$failed" = 0 ]; }
