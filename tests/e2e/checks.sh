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

# worse_frames REF A B LOG: the frames (snapshot names in directory REF) where A
# is further from REF than B is: a PSNR more than 0.5 dB lower, or more than 0.1
# points more of the pixels differing; each frame's figures appended to LOG as
# "FRAME psnr_A diff%_A psnr_B diff%_B".  Prints the frames, space-separated; a
# frame missing from A or B is one of them.
worse_frames() {
    for f in $(ls "$1"); do
        "$build/tools/fp-compare" --format=kv "$1/$f" "$2/$f" > "$4.a"
        "$build/tools/fp-compare" --format=kv "$1/$f" "$3/$f" > "$4.b"
        pa=$(sed -n 's/^psnr=//p' "$4.a") da=$(sed -n 's/^diff_percent=//p' "$4.a")
        pb=$(sed -n 's/^psnr=//p' "$4.b") db=$(sed -n 's/^diff_percent=//p' "$4.b")
        echo "$f $pa $da $pb $db" >> "$4"
        # a frame fp-compare could not read counts as worse
        awk -v pa="$pa" -v pb="$pb" -v da="$da" -v db="$db" 'BEGIN {
            if (pa == "" || pb == "" || da == "" || db == "") exit 0;
            if (pa == "inf") pa = 1e9; if (pb == "inf") pb = 1e9;
            exit !(pa + 0.5 < pb || da > db + 0.1) }' && printf ' %s' "$f"
    done
    rm -f "$4.a" "$4.b"
}
