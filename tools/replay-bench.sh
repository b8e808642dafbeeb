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
# number.
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

median() { sort -n | awk '{ v[NR] = $1 } END { if (NR) print (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2); else print "n/a" }'; }

frames=$(apitrace info "$trace" | sed -n 's/.*"FramesCount": \([0-9]*\).*/\1/p')
nscenes=$(echo $scenes | wc -w) scene_frames=""
if [ "$nscenes" -gt 0 ]; then
    [ $((frames % nscenes)) -eq 0 ] && [ $((frames / nscenes)) -ge 2 ] ||
        { echo "replay-bench: $frames frames do not divide into the $nscenes scenes of --scenes" >&2; exit 2; }
    scene_frames=$((frames / nscenes))
fi
echo "replay benchmark: $(basename "$trace"), $frames frames, $runs run(s) a configuration, $(nproc) cores"
printf 'config\trun\treplay_s\tfirst_frame_s\tmean_err\tworst_psnr\tframes_compared\n' > "$out/results.tsv"
declare -A replay first err psnr
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
            # mean of the frames' mean errors; the worst frame's PSNR
            read -r e p < <(for f in "$out"/llvmpipe.1.snap/*.png; do
                    "$compare" "$snapdir/$(basename "$f")" "$f" --format=kv 2>/dev/null |
                        awk -F= '$1 == "mean_err" { m = $2 } $1 == "psnr" { q = $2 } END { print m, q }'
                done | awk '{ s += $1; if (NR == 1 || ($2 != "inf" && ($2 + 0 < w || w == "inf"))) w = $2 }
                            END { if (NR) printf "%.4f %s\n", s / NR, w; else print "n/a n/a" }')
        fi
        f=$(run "$c" "$first" "$out/$c.$r.first.log")
        printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$c" "$r" "$w" "$f" "$e" "$p" "$n" >> "$out/results.tsv"
    done
done
for c in $configs; do
    replay[$c]=$(awk -F'\t' -v c="$c" '$1 == c && $3 != "n/a" { print $3 }' "$out/results.tsv" | median)
    first[$c]=$(awk -F'\t' -v c="$c" '$1 == c { print $4 }' "$out/results.tsv" | median)
    err[$c]=$(awk -F'\t' -v c="$c" '$1 == c { print $5 }' "$out/results.tsv" | tail -1)
    psnr[$c]=$(awk -F'\t' -v c="$c" '$1 == c { print $6 }' "$out/results.tsv" | tail -1)
done

ratio() { awk -v a="$1" -v b="${2:-}" 'BEGIN { if (a+0 > 0 && b+0 > 0) printf "%.2f", a / b; else print "n/a" }'; }
echo
echo "| configuration | replay (s) | fps | time ÷ llvmpipe's | softpipe's time ÷ this | mean error vs llvmpipe (0–255) | worst frame PSNR (dB) | first frame (s) |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
for c in $configs; do
    fps=$(awk -v s="${replay[$c]}" -v n="$frames" 'BEGIN { if (s+0 > 0) printf "%.1f", n / s; else print "n/a" }')
    echo "| $c | ${replay[$c]} | $fps | $(ratio "${replay[$c]}" "${replay[llvmpipe]:-}") | $(ratio "${replay[softpipe]:-}" "${replay[$c]}") | ${err[$c]} | ${psnr[$c]} | ${first[$c]} |"
done

# the same ratios round by round (each round's two runs a few minutes apart): their
# median, and the range over the rounds
round_ratio() { # NUM DEN: the ratio of the two configurations' replays in each round
    awk -F'\t' -v a="$1" -v b="$2" 'NR > 1 && $3 != "n/a" { t[$1, $2] = $3; if ($2 + 0 > n) n = $2 + 0 }
        END { for (r = 1; r <= n; r++) if (t[a, r] > 0 && t[b, r] > 0) printf "%.3f\n", t[a, r] / t[b, r] }' \
        "$out/results.tsv"
}
ratio_summary() { # NUM DEN: "median (min–max)" of the rounds' ratios
    local r
    r=$(round_ratio "$1" "$2" | sort -n)
    [ -n "$r" ] || { echo n/a; return; }
    printf '%.2f (%.2f–%.2f)' "$(median <<< "$r")" "$(head -1 <<< "$r")" "$(tail -1 <<< "$r")"
}
if [ "$runs" -gt 1 ]; then
    echo
    echo "| configuration | time ÷ llvmpipe's, per round | softpipe's time ÷ this, per round |"
    echo "|---|---:|---:|"
    for c in $configs; do
        [ "$c" != llvmpipe ] || continue
        sp=n/a
        [[ " $configs " != *" softpipe "* ]] || sp=$(ratio_summary softpipe "$c")
        echo "| $c | $(ratio_summary "$c" llvmpipe) | $sp |"
    done
    if [[ " $configs " == *" fixpipe "* && " $configs " == *" fixpipe-1thread "* ]]; then
        echo
        echo "fixpipe's speed-up on $(nproc) cores (fixpipe-1thread's time ÷ fixpipe's), per round: $(ratio_summary fixpipe-1thread fixpipe)"
    fi
    if [[ " $configs " == *" llvmpipe-1thread "* ]]; then
        echo "llvmpipe's speed-up on $(nproc) cores (llvmpipe-1thread's time ÷ llvmpipe's), per round: $(ratio_summary llvmpipe-1thread llvmpipe)"
    fi
fi

# per scene: frames 2..N of each scene from the frame-end timestamps of each run's
# log (ns; a trace's last frame may have no swap: that scene's time is scaled from
# its frames timed), the median over the runs; and fixpipe's skips from its counters
# after every frame of one more replay, not timed (the counts are the same in every
# run; cumulative per GL context: a frame number that does not grow starts a context).
# The counters cost the replay about 2%, so no timed run prints them: the two
# thread counts, and fixpipe against llvmpipe, compare like with like.
scene_times() { # LOG: one line of seconds per scene
    awk -v n="$scene_frames" -v k="$nscenes" '$1 == "rendering_finished" { t[f++] = $2 }
        END { for (s = 0; s < k; s++) { a = s * n; b = a + n - 1; if (b > f - 1) b = f - 1
                  if (b > a) printf "%.3f\n", (t[b] - t[a]) / 1e9 * (n - 1) / (b - a); else print "n/a" } }' "$1"
}
if [ "$nscenes" -gt 0 ]; then
    declare -A sec each
    for c in $configs; do
        for r in $(seq 1 "$runs"); do
            [ -r "$out/$c.$r.log" ] || continue
            i=0
            while read -r v; do each[$c.$i]+="$v "; i=$((i + 1)); done < <(scene_times "$out/$c.$r.log")
        done
        for ((i = 0; i < nscenes; i++)); do
            sec[$c.$i]=$(tr ' ' '\n' <<< "${each[$c.$i]:-}" | { grep -vx -e '' -e 'n/a' || true; } | median)
        done
    done
    # fixpipe's shares: constant 1/w of the quads divided, constant components of the
    # component-quads, texture quads without a LOD of those with a LOD from differences,
    # texture quad-axes addressed per column or row of the texture quads' two axes,
    # quads shaded without gl_FragCoord of all quads, quads without a Z walk of all
    # quads, quads left unshaded by the early tests or for want of a visible effect of
    # all quads
    shares=()
    if [[ " $configs " == *" fixpipe "* ]]; then
        run fixpipe-stats "$trace" "$out/fixpipe.stats.log" >/dev/null
        mapfile -t shares < <(sed -n 's/^fixpipe work at frame \([0-9]*\): /\1 /p' "$out/fixpipe.stats.log" |
            awk -v n="$scene_frames" -v k="$nscenes" '
            BEGIN { split("divided skip_w comp_quads skip_comp lod_quads skip_lod tex_quads skip_axes quads skip_fragcoord quads skip_z quads skip_unshaded", key, " ") }
            { if ($1 + 0 <= frame + 0) for (x in p) p[x] = 0
              frame = $1; sc = int(line / n); line++
              for (i = 2; i < NF; i += 2) { d[sc, $i] += $(i + 1) - p[$i]; p[$i] = $(i + 1) }
              d[sc, "skip_unshaded"] = d[sc, "skip_early"] + d[sc, "skip_shade"] }
            END { for (s = 0; s < k; s++) { out = ""
                      for (j = 1; j <= 14; j += 2) { tot = d[s, key[j]] * (j == 7 ? 2 : 1); sk = d[s, key[j + 1]]
                          out = out (tot > 0 ? sprintf("%.0f%%", 100 * sk / tot) : "–") " " }
                      print out } }')
    fi
    echo
    printf '| scene (frames 2–%s) |' "$scene_frames"
    for c in $configs; do printf ' %s (s) |' "$c"; done
    printf ' fixpipe ÷ llvmpipe | softpipe ÷ fixpipe | constant 1/w | constant components | texture quads without LOD | texture quad-axes per column or row | quads without gl_FragCoord | quads without a Z walk | quads not shaded (early tests, no effect) |\n|---|'
    for c in $configs; do printf -- '---:|'; done
    echo '---:|---:|---:|---:|---:|---:|---:|---:|---:|'
    i=0
    for sc in $scenes; do
        printf '| %s |' "$sc"
        for c in $configs; do printf ' %s |' "${sec[$c.$i]:-n/a}"; done
        read -r sw scc sl sa sf sz su <<< "${shares[$i]:-n/a n/a n/a n/a n/a n/a n/a}"
        echo " $(ratio "${sec[fixpipe.$i]:-}" "${sec[llvmpipe.$i]:-}") | $(ratio "${sec[softpipe.$i]:-}" "${sec[fixpipe.$i]:-}") | $sw | $scc | $sl | $sa | $sf | $sz | $su |"
        i=$((i + 1))
    done
    # each driver's speed-up on the machine's cores, scene by scene: where the
    # second thread's time goes is easier seen than read
    speedup_pairs=()
    [[ " $configs " != *" fixpipe "* || " $configs " != *" fixpipe-1thread "* ]] ||
        speedup_pairs+=("fixpipe 200,40,40")
    [[ " $configs " != *" llvmpipe-1thread "* ]] || speedup_pairs+=("llvmpipe 40,160,60")
    if [ ${#speedup_pairs[@]} -gt 0 ] && [ -x "$root/tools/fp-plot" ]; then
        echo
        printf '| scene | speed-up on %s cores:' "$(nproc)"
        for pr in "${speedup_pairs[@]}"; do printf ' %s |' "${pr%% *}"; done
        printf '\n|---|'
        for pr in "${speedup_pairs[@]}"; do printf -- '---:|'; done
        echo
        i=0
        for sc in $scenes; do
            printf '| %s |' "$sc"
            for pr in "${speedup_pairs[@]}"; do
                d=${pr%% *}
                printf ' %s |' "$(ratio "${sec[$d-1thread.$i]:-}" "${sec[$d.$i]:-}")"
            done
            echo
            i=$((i + 1))
        done
        {
            echo "title speed-up on $(nproc) cores, scene by scene (frames 2-$scene_frames)"
            echo "xlabel scene, in the trace's order"
            echo "ylabel one thread's time / all cores' time"
            echo "legend bl"
            echo "yrange 1 $(nproc).1"
            # points, not lines: the scenes are in the trace's order, nothing
            # lies between them; the first driver's points carry the names
            label=1
            for pr in "${speedup_pairs[@]}"; do
                d=${pr%% *}
                echo "series ${pr#* } points $d"
                i=0
                for sc in $scenes; do
                    v=$(ratio "${sec[$d-1thread.$i]:-}" "${sec[$d.$i]:-}")
                    [ "$v" = n/a ] || echo "$((i + 1)) $v${label:+ $sc}"
                    i=$((i + 1))
                done
                label=
            done
            echo "series 120,120,120 line $(nproc)x (every thread busy all the time)"
            echo "1 $(nproc)"
            echo "$nscenes $(nproc)"
        } > "$out/speedup.txt"
        "$root/tools/fp-plot" "$out/speedup.txt" "$out/speedup-per-scene.png" --size 720x420 >/dev/null 2>&1 &&
            echo "chart: $out/speedup-per-scene.png"
    fi
fi

# the chart: replay time (log) against mean error, one point per configuration
chart=$root/tools/fp-plot
if [ -x "$chart" ]; then
    {
        echo "title replay time against error"
        echo "xlabel replay time (s, log)"
        echo "ylabel mean error vs llvmpipe (0-255)"
        echo "logx"
        echo "legend tl"
        echo "yrange 0 0.05"
        for c in $configs; do
            [ "$c" != llvmpipe ] || continue
            case $c in
            fixpipe) rgb=200,40,40 ;; fixpipe-before) rgb=120,120,120 ;; fixpipe-nojit) rgb=230,140,30 ;;
            fixpipe-jitall) rgb=160,40,160 ;; fixpipe-1thread) rgb=230,120,120 ;; llvmpipe-1thread) rgb=120,200,120 ;; fixpipe-scalar) rgb=150,90,40 ;; softpipe) rgb=40,90,200 ;; *) rgb=0,0,0 ;;
            esac
            [ "${replay[$c]}" != n/a ] && [ "${err[$c]}" != n/a ] || continue
            echo "series $rgb points $c"
            echo "${replay[$c]} ${err[$c]}"
        done
        echo "series 40,160,60 points llvmpipe (the reference)"
        echo "${replay[llvmpipe]} 0"
    } > "$out/chart.txt"
    "$chart" "$out/chart.txt" "$out/replay-time-vs-error.png" --size 720x420 >/dev/null 2>&1 &&
        echo "chart: $out/replay-time-vs-error.png"
fi

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
    a=$(awk '$1 == "this" { print $2 }' "$out/piglit-$l.times" | median)
    ea=$(awk '$1 == "this" { print $3 }' "$out/piglit-$l.times" | paste -sd, -)
    b=n/a eb="" d=n/a ed=""
    if [ -n "$before" ]; then
        b=$(awk '$1 == "before" { print $2 }' "$out/piglit-$l.times" | median)
        eb=$(awk '$1 == "before" { print $3 }' "$out/piglit-$l.times" | paste -sd, -)
        d=$(awk '$1 == "driver" { print $2 }' "$out/piglit-$l.times" | median)
        ed=$(awk '$1 == "driver" { print $3 }' "$out/piglit-$l.times" | paste -sd, -)
    fi
    echo "| $l | $piglit_runs | $a | $ea | $b | $eb | $d | $ed |"
done
