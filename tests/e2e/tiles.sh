#!/bin/sh
# Windows larger than the seed profile's X_out (docs/tiles.md): glmark2-es2
# recorded at 3000x2000 and 4096x2160 (traces/tiles), replayed headless
# through llvmpipe, fixpipe `wide` (one pass: X_out is 13 bits there) and
# fixpipe `seed` (tiles of 2048) on one thread and on two.  Checks, per trace:
#   each replay's GL_RENDERER is the driver and profile asked for;
#   seed on 1 and 2 threads: every frame the same bytes;
#   every frame of seed is within the error of wide against llvmpipe: PSNR
#   at most 0.5 dB lower, at most 0.1 points more of the pixels differing.
# One line per check, then "N passed, N failed"; exit 1 on a failure.
checks=tiles
. "$(dirname "$0")/checks.sh"

# replay TRACE DIR DRIVER PROFILE [VAR=value...]: snapshots of every frame in DIR
replay() {
    trace=$1 dir=$2 drv=$3 prof=$4
    shift 4
    mkdir -p "$dir"
    env "$@" "$root/fixpipe" run --no-xvfb --driver "$drv" --profile "$prof" -- \
        env WAFFLE_PLATFORM=surfaceless_egl eglretrace --headless --snapshot-prefix="$dir/" \
        "$trace" > "$dir.log" 2>&1
}

# renderer TRACE DRIVER PROFILE: GL_RENDERER at the trace's first frame
renderer() {
    first=$(ls "$out/$name/llvmpipe" | head -n 1 | sed 's/\.png$//; s/^0*//')
    "$root/fixpipe" run --no-xvfb --driver "$2" --profile "$3" -- \
        env WAFFLE_PLATFORM=surfaceless_egl eglretrace --headless --dump-state="${first:-0}" \
        "$1" 2>/dev/null | sed -n 's/.*"GL_RENDERER": "\([^"]*\)".*/\1/p'
}

for trace in "$root"/traces/tiles/*.trace; do
    name=$(basename "$trace" .trace)
    d=$out/$name
    if ! replay "$trace" "$d/llvmpipe" llvmpipe seed ||
       ! replay "$trace" "$d/wide" fixpipe wide ||
       ! replay "$trace" "$d/seed" fixpipe seed FIXPIPE_DEBUG=nothreads ||
       ! replay "$trace" "$d/seed2" fixpipe seed FIXPIPE_THREADS=2; then
        fail "$name: a replay failed ($(tail -q -n 1 "$d"/*.log | grep -iv '^wrote' | head -n 1))"
        continue
    fi
    n=$(ls "$d/llvmpipe" | wc -l)
    for m in wide seed seed2; do
        if [ "$(ls "$d/$m" | wc -l)" != "$n" ] || [ "$n" = 0 ]; then
            fail "$name: $m has $(ls "$d/$m" | wc -l) frames, llvmpipe $n"
            continue 2
        fi
    done
    r_seed=$(renderer "$trace" fixpipe seed) r_wide=$(renderer "$trace" fixpipe wide)
    if [ "$r_seed" = "fixpipe (seed)" ] && [ "$r_wide" = "fixpipe (wide)" ]; then
        pass "$name: replayed by '$r_seed' and '$r_wide'"
    else
        fail "$name: GL_RENDERER '$r_seed' and '$r_wide', not fixpipe (seed) and fixpipe (wide)"
    fi
    if diff -rq "$d/seed" "$d/seed2" > "$d/threads.diff" 2>&1; then
        pass "$name: $n frames, seed on 1 thread = 2 threads"
    else
        fail "$name: $(wc -l < "$d/threads.diff") of $n frames differ between 1 and 2 threads"
    fi
    worse=$(worse_frames "$d/llvmpipe" "$d/seed" "$d/wide" "$d/frames.txt")
    worst=$(awk '{ print $2 }' "$d/frames.txt" | sort -g | head -n 1)
    if [ -z "$worse" ]; then
        pass "$name: $n frames of seed within wide's error against llvmpipe (worst $worst dB)"
    else
        fail "$name: seed further from llvmpipe than wide in frames$worse (see $d/frames.txt)"
    fi
done
checks_end
