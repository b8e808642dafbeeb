#!/bin/sh
# The interpolators of Z and colour (FIXPIPE_INTERP, docs/interp-modes.md) on
# real programs: checked-in traces replayed headless through llvmpipe and
# through fixpipe in each mode, measured (MODE:error) with FIXPIPE_STATS=1 (the
# statistics at exit).
# Checks, per trace:
#   barycentric and vector cover what scanline covers: the model's quads and
#   pixels covered are the same numbers;
#   each mode measured its registers on real content (a nonzero count of
#   values against exact arithmetic);
#   every frame of each mode is within scanline's error against llvmpipe:
#   PSNR at most 0.5 dB lower, at most 0.1 points more of the pixels differing.
# One line per check, then "N passed, N failed"; exit 1 on a failure.
checks=interp-modes
. "$(dirname "$0")/checks.sh"

# replay TRACE DIR DRIVER [VAR=value...]: snapshots of every frame in DIR
replay() {
    trace=$1 dir=$2 drv=$3
    shift 3
    mkdir -p "$dir"
    env "$@" "$root/fixpipe" run --no-xvfb --driver "$drv" -- \
        env WAFFLE_PLATFORM=surfaceless_egl eglretrace --headless --snapshot-prefix="$dir/" \
        "$trace" > "$dir.log" 2>&1
}

# stat LOG KEY: quads or pixels covered, summed over the contexts
stat() { grep -o "^  quads [0-9][0-9]* pixels covered [0-9][0-9]*" "$1" |
         awk -v k="$2" '{ s += (k == "quads" ? $2 : $5) } END { print s + 0 }'; }

for name in glmark2-build-vbo glmark2-shadow es2gears; do
    trace=$root/traces/recorded/$name.trace
    d=$out/$name
    if ! replay "$trace" "$d/llvmpipe" llvmpipe; then
        fail "$name: the llvmpipe replay failed"
        continue
    fi
    for m in scanline barycentric vector; do
        if ! replay "$trace" "$d/$m" fixpipe FIXPIPE_STATS=1 FIXPIPE_INTERP=$m:error; then
            fail "$name: the $m replay failed ($(tail -n 1 "$d/$m.log"))"
            continue 2
        fi
    done
    n=$(ls "$d/llvmpipe" | wc -l)
    q0=$(stat "$d/scanline.log" quads) p0=$(stat "$d/scanline.log" "pixels covered")
    for m in barycentric vector; do
        q=$(stat "$d/$m.log" quads) p=$(stat "$d/$m.log" "pixels covered")
        if [ -n "$q0" ] && [ "$q0" != 0 ] && [ "$q" = "$q0" ] && [ "$p" = "$p0" ]; then
            pass "$name: $m covers what scanline covers ($p0 pixels in $q0 quads)"
        else
            fail "$name: $m covers $p pixels in $q quads, scanline $p0 in $q0"
        fi
    done
    for m in scanline barycentric vector; do
        v=$(sed -n 's/^  interpolator error, z: \([0-9]*\) values.*/\1/p' "$d/$m.log" |
            awk '{ s += $1 } END { print s + 0 }')
        if [ -n "$v" ] && [ "$v" -gt 0 ]; then
            pass "$name: $m measured $v Z values against exact arithmetic"
        else
            fail "$name: $m measured no Z value ('$v')"
        fi
    done
    for m in barycentric vector; do
        if [ "$(ls "$d/$m" | wc -l)" != "$n" ] || [ "$n" = 0 ]; then
            fail "$name: $m has $(ls "$d/$m" | wc -l) frames, llvmpipe $n"
            continue
        fi
        worse=$(worse_frames "$d/llvmpipe" "$d/$m" "$d/scanline" "$d/frames-$m.txt")
        if [ -z "$worse" ]; then
            pass "$name: $n frames of $m within scanline's error against llvmpipe"
        else
            fail "$name: $m further from llvmpipe than scanline in frames$worse (see $d/frames-$m.txt)"
        fi
    done
done
checks_end
