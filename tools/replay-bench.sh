#!/bin/bash
# The replay benchmark: one long apitrace of glmark2-es2 scenes at 640x480
# (traces/bench/glmark2-long.trace, 1800 frames of build, texture, phong, bump,
# effect2d, pulsar, desktop, jellyfish and ideas, recorded once through llvmpipe)
# replayed with `eglretrace -b` through every driver in one run, in turn, on a
# virtual X server.  Prints each configuration's replay time (the whole process:
# start-up, shader compilation, 1800 frames), its ratios to llvmpipe and softpipe,
# its error against llvmpipe (every 100th frame is snapshotted: mean absolute error
# 0-255 over the frames, and the worst frame's PSNR), and the first-frame latency
# (the whole process replaying the trace's first frame alone); then the same per
# scene (the trace's frames in equal runs, --scenes): each configuration's time for
# the scene's frames 2 to N, the median of the runs (eglretrace --pframe-times: the
# scene's first frame, with its set-up, counts in the whole replay only), and for
# fixpipe the share of each skip taken (FIXPIPE_STATS=frames:N, docs/datapath.md),
# from one more replay after the timed ones (the counts are the same in every run;
# no timed configuration prints counters); with fixpipe-1thread or llvmpipe-1thread,
# each driver's speed-up on the machine's cores scene by scene, as a table and a
# chart (OUT/speedup-per-scene.png).  A benchmark, not a test: it never fails on a
# number.  This script runs the drivers; tools/replay-bench-report computes and prints
# the figures and draws the charts from the files the runs leave in OUT, and can print
# them again from an OUT (`tools/replay-bench-report report --help`).
#
#   tools/replay-bench.sh [--runs N] [--configs "NAME ..."] [--before WORKDIR]
#                         [--piglit "LIST ..."] [--piglit-runs N] [--trace FILE] [--out DIR]
#                         [--scenes "NAME ..."]
#
# Configurations (NAME):
#   fixpipe          the default: compiled shaders, tiered (docs/jit.md)
#   fixpipe-scalar   FIXPIPE_DEBUG=scalar,noskip: the model's scalar reference datapath,
#                    nothing skipped (docs/datapath.md): the same bits, the time before lanes
#   fixpipe-1thread  FIXPIPE_THREADS=1: the model on one thread (docs/threads.md)
#   fixpipe-jitall   FIXPIPE_DEBUG=jitall: every fragment shader compiled at first use
#   fixpipe-nojit    FIXPIPE_DEBUG=nojit: tgsi_exec for every shader, draw without LLVM
#   fixpipe-barycentric, fixpipe-vector
#                    FIXPIPE_INTERP=barycentric|vector: Z and colour by seed 001's or
#                    seed 002's per-pixel interpolator (docs/interp-modes.md)
#   fixpipe-before   the fixpipe of another build: --before WORKDIR (its .fixpipe/,
#                    e.g. a worktree of an earlier commit after its ./fixpipe setup)
#   softpipe         our Mesa build (with LLVM: draw compiles vertex shaders)
#   llvmpipe         Debian's system Mesa, the reference (always run, first)
#   llvmpipe-1thread LP_NUM_THREADS=0: llvmpipe drawing on the calling thread, so that
#                    the reference's own speed-up on the machine's cores is measured
#                    in the same run as fixpipe's (docs/threads.md)
# Default: fixpipe fixpipe-1thread fixpipe-scalar fixpipe-nojit softpipe llvmpipe llvmpipe-1thread
# (+ fixpipe-before with --before).
# --scenes: the names of the trace's scenes in order, each the same number of frames
# (default: the checked-in trace's build texture phong bump effect2d pulsar desktop
# jellyfish ideas; "" leaves out the per-scene table).
# --piglit "gles2 texture" also times `./fixpipe piglit LIST` through fixpipe, and with
# --before the same list through the other checkout's launcher and build, and through this
# launcher (this tree's piglit runner) with the other checkout's build: the driver alone
# compared; --piglit-runs N (default 1) runs each N times, the three alternating, and prints
# the medians (a list of short processes is noisy on a shared machine).
# The runs go round by round, each configuration once a round in the same order, so
# that a machine whose speed drifts over minutes weighs on every configuration alike.
# The median of --runs runs (default 1) is printed, and with several runs the ratios
# of each round's runs (their median and range); every run's figures are in
# OUT/results.tsv (default out/replay-bench).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
runs=1 configs="" before="" piglit_lists="" piglit_runs=1 out=$root/out/replay-bench
scenes="build texture phong bump effect2d pulsar desktop jellyfish ideas"
trace=$root/traces/bench/glmark2-long.trace
while [ $# -gt 0 ]; do
    case $1 in
    --runs) runs=$2; shift 2 ;;
    --configs) configs=$2; shift 2 ;;
    --before) before=$(cd "$2" && pwd); shift 2 ;;
    --trace) trace=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --piglit) piglit_lists=$2; shift 2 ;;
    --piglit-runs) piglit_runs=$2; shift 2 ;;
    --scenes) scenes=$2; shift 2 ;;
    -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "replay-bench: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done
[ -r "$trace" ] || { echo "replay-bench: no trace $trace" >&2; exit 2; }
if [ -z "$configs" ]; then
    configs="fixpipe fixpipe-1thread fixpipe-scalar fixpipe-nojit softpipe llvmpipe llvmpipe-1thread"
    [ -z "$before" ] || configs="fixpipe-before $configs"
fi
# llvmpipe first: its snapshots are the reference
configs="llvmpipe $(echo "$configs" | tr ' ' '\n' | { grep -vx llvmpipe || true; } | tr '\n' ' ')"
for c in $configs; do
    case $c in
    fixpipe|fixpipe-1thread|fixpipe-scalar|fixpipe-jitall|fixpipe-nojit|softpipe|llvmpipe|llvmpipe-1thread) ;;
    fixpipe-barycentric|fixpipe-vector) ;;
    fixpipe-before) [ -n "$before" ] || { echo "replay-bench: fixpipe-before needs --before WORKDIR" >&2; exit 2; } ;;
    *) echo "replay-bench: unknown configuration '$c' (accepted: fixpipe, fixpipe-1thread, fixpipe-scalar, fixpipe-jitall, fixpipe-nojit, fixpipe-barycentric, fixpipe-vector, fixpipe-before, softpipe, llvmpipe, llvmpipe-1thread)" >&2; exit 2 ;;
    esac
done
mkdir -p "$out"
compare=$root/build/std/tools/fp-compare
report=$root/tools/replay-bench-report
[ -x "$compare" ] || { echo "replay-bench: no $compare (./fixpipe setup)" >&2; exit 2; }
# every 100th frame's swap
snaps=$(apitrace dump --grep=eglSwapBuffers --arg-names=no "$trace" 2>/dev/null |
        sed -n 's/^\([0-9][0-9]*\) .*/\1/p' | awk 'NR % 100 == 0' | paste -sd, -)
[ -n "$snaps" ] || { echo "replay-bench: no eglSwapBuffers in $trace" >&2; exit 2; }
first=$out/first-frame.trace
apitrace trim --frames=0 -o "$first" "$trace" >/dev/null 2>&1 ||
    { echo "replay-bench: apitrace trim failed" >&2; exit 1; }

# run CONFIG TRACE LOG [eglretrace options]: the replay through one configuration;
# prints the whole process's wall seconds
run() {
    local c=$1 t=$2 log=$3 driver=$c work=${FIXPIPE_WORK:-} envs=()
    shift 3
    case $c in
    fixpipe-scalar) driver=fixpipe; envs=(FIXPIPE_DEBUG=scalar,noskip) ;;
    fixpipe-jitall) driver=fixpipe; envs=(FIXPIPE_DEBUG=jitall) ;;
    fixpipe-1thread) driver=fixpipe; envs=(FIXPIPE_THREADS=1) ;;
    fixpipe-nojit) driver=fixpipe; envs=(FIXPIPE_DEBUG=nojit) ;;
    fixpipe-barycentric) driver=fixpipe; envs=(FIXPIPE_INTERP=barycentric) ;;
    fixpipe-vector) driver=fixpipe; envs=(FIXPIPE_INTERP=vector) ;;
    fixpipe-before) driver=fixpipe; work=$before/.fixpipe ;;
    fixpipe-stats) driver=fixpipe; envs=(FIXPIPE_STATS=frames:1) ;;
    llvmpipe-1thread) driver=llvmpipe; envs=(LP_NUM_THREADS=0) ;;
    esac
    local t0 t1
    t0=$(date +%s.%N)
    FIXPIPE_WORK=${work:-$root/.fixpipe} "$root/fixpipe" run --xvfb --driver "$driver" -- \
        env "${envs[@]}" eglretrace -b "$@" "$t" > "$log" 2>&1 || true
    t1=$(date +%s.%N)
    awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }'
}

frames=$(apitrace info "$trace" | sed -n 's/.*"FramesCount": \([0-9]*\).*/\1/p')
nscenes=$(echo $scenes | wc -w)
# checked before the runs, not only by the report after them
if [ "$nscenes" -gt 0 ]; then
    [ $((frames % nscenes)) -eq 0 ] && [ $((frames / nscenes)) -ge 2 ] ||
        { echo "replay-bench: $frames frames do not divide into the $nscenes scenes of --scenes" >&2; exit 2; }
fi
echo "replay benchmark: $(basename "$trace"), $frames frames, $runs run(s) a configuration, $(nproc) cores"
printf 'config\trun\treplay_s\tfirst_frame_s\tmean_err\tworst_psnr\tframes_compared\n' > "$out/results.tsv"
# round by round, every configuration once a round in the same order: on a machine
# whose speed drifts within minutes, each configuration then sees the same drift, and
# the ratios of one round compare runs a few minutes apart
for r in $(seq 1 "$runs"); do
    for c in $configs; do
        snapdir=$out/$c.$r.snap
        rm -rf "$snapdir"; mkdir -p "$snapdir"
        w=$(run "$c" "$trace" "$out/$c.$r.log" --pframe-times --snapshot-prefix="$snapdir/" \
              --snapshot="$snaps")
        n=$(find "$snapdir" -name '*.png' | wc -l)
        [ "$n" -gt 0 ] || { echo "  $c: the replay failed (log $out/$c.$r.log)"; w=n/a; }
        e=n/a p=n/a
        if [ "$c" != llvmpipe ] && [ "$n" -gt 0 ]; then
            # each snapshot against llvmpipe's, kept beside it as NAME.kv; the run's
            # mean of the frames' mean errors and its worst frame's PSNR
            for f in "$out"/llvmpipe.1.snap/*.png; do
                [ -e "$f" ] || continue
                name=$(basename "$f" .png)
                "$compare" "$snapdir/$name.png" "$f" --format=kv > "$snapdir/$name.kv" 2>/dev/null || true
            done
            read -r e p <<< "$("$report" errors "$snapdir")"
        fi
        f=$(run "$c" "$first" "$out/$c.$r.first.log")
        printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$c" "$r" "$w" "$f" "$e" "$p" "$n" >> "$out/results.tsv"
    done
done

# fixpipe's counters after every frame, for its shares of skipped work per scene:
# one more replay, not timed (the counts are the same in every run).  The counters
# cost the replay about 2%, so no timed run prints them: the two thread counts, and
# fixpipe against llvmpipe, compare like with like.
if [ "$nscenes" -gt 0 ] && [[ " $configs " == *" fixpipe "* ]]; then
    run fixpipe-stats "$trace" "$out/fixpipe.stats.log" >/dev/null
fi
"$report" report "$out" --configs "$configs" --frames "$frames" --scenes "$scenes" --nproc "$(nproc)"

[ -n "$piglit_lists" ] || exit 0
# piglit lists: wall time of the whole `./fixpipe piglit LIST` (its own expectations
# decide the exit status, printed as is)
echo
echo "| piglit list (fixpipe) | runs | this tree, median (s) | exit statuses | before, median (s) | exit statuses | before's build with this runner, median (s) | exit statuses |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
# list_time DIR WORK LIST LOG: one `./fixpipe piglit LIST` of the checkout DIR with the
# build in WORK; prints "SECONDS EXIT"
list_time() {
    local t0 rc=0
    t0=$(date +%s.%N)
    (cd "$1" && FIXPIPE_WORK=$2 ./fixpipe piglit "$3" --driver fixpipe) > "$4" 2>&1 || rc=$?
    awk -v a="$t0" -v b="$(date +%s.%N)" -v rc="$rc" 'BEGIN { printf "%.1f %s\n", b - a, rc }'
}
for l in $piglit_lists; do
    : > "$out/piglit-$l.times"
    for r in $(seq 1 "$piglit_runs"); do
        echo "this $(list_time "$root" "${FIXPIPE_WORK:-$root/.fixpipe}" "$l" "$out/piglit-$l.$r.log")" \
            >> "$out/piglit-$l.times"
        [ -z "$before" ] ||
            echo "before $(list_time "$before" "$before/.fixpipe" "$l" "$out/piglit-$l.$r.before.log")" \
                >> "$out/piglit-$l.times"
        [ -z "$before" ] ||
            echo "driver $(list_time "$root" "$before/.fixpipe" "$l" "$out/piglit-$l.$r.driver.log")" \
                >> "$out/piglit-$l.times"
    done
    "$report" piglit "$out/piglit-$l.times" --list "$l"
done
