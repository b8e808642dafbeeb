#!/bin/sh
# The demo: renders tools/fp-demo through fixpipe, llvmpipe and (for a
# reference of what a second correct driver does) softpipe, writes the PNGs
# and difference heat maps to OUTDIR and prints the comparison figures and
# the render times: the first frame, the warm-up frames (start-up, and the
# frames before fixpipe has compiled its shaders) and the steady state, the
# mean of the frames after them, which is what a program gets.  ./fixpipe
# demo calls this after setup.
#
#   tools/demo.sh OUTDIR [--scene gouraud|mesh|textured|all] [--size WxH]
#                 [--frames N] [--warmup W (default N/3)] [--build-dir build/std]
#                 [--drivers "fixpipe llvmpipe softpipe"]
#
# Exit 0 when every driver rendered, 1 if one failed, 2 on a usage error.
set -u

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
build=${FP_BUILD_DIR:-$root/build/std}
scene=all size=512x512 frames=30 warmup=
drivers="fixpipe llvmpipe softpipe"
ref=llvmpipe

usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
[ $# -ge 1 ] || usage
case $1 in -h|--help) usage ;; -*) usage ;; esac
out=$1
shift
while [ $# -gt 0 ]; do
    case $1 in
    --scene) scene=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --warmup) warmup=$2; shift 2 ;;
    --build-dir) build=$2; shift 2 ;;
    --drivers) drivers=$2; shift 2 ;;
    *) echo "demo.sh: unknown argument '$1'" >&2; usage ;;
    esac
done

# the warm-up: a third of the frames unless given
[ -n "$warmup" ] || warmup=$((frames > 3 ? frames / 3 : 1))

. "$here/fp-run-driver.sh"

demo=$build/tools/fp-demo
compare=$build/tools/fp-compare
for b in "$demo" "$compare"; do
    [ -x "$b" ] || { echo "demo.sh: $b is not built (meson in $build, or --build-dir)" >&2; exit 2; }
done
mkdir -p "$out" || exit 2

status=0
rendered=""
echo "fixpipe demo: scene '$scene', $size, $frames frames per driver, the first $warmup the warm-up; output in $out"
echo
printf '%-10s %-40s %12s %12s %12s   %s\n' driver renderer "first frame" "warm-up" "per frame" \
    "modeled chip (docs/cycles.md)"
for d in $drivers; do
    log=$out/$d.log
    if fp_run_driver "$d" "$demo" --scene "$scene" --size "$size" --frames "$frames" \
            --warmup "$warmup" -o "$out/$d.png" >"$log" 2>&1; then
        r=$(sed -n 's/^renderer: //p' "$log")
        first=$(sed -n 's/^first_frame_ms: //p' "$log")
        warm=$(sed -n 's/^warmup_frames: [0-9]* ms: //p' "$log")
        per=$(sed -n 's/^frames: .* ms_per_frame: \([0-9.]*\).*/\1/p' "$log")
        # A mislaid library path renders through the wrong driver: say so.
        if ! printf '%s' "$r" | grep -qi -- "$d"; then
            printf '%-10s FAILED: GL_RENDERER is "%s", not %s\n' "$d" "$r" "$d"
            status=1
            continue
        fi
        modeled=$(sed -n 's/^modeled_cycles_per_frame: \([0-9]*\) modeled_ms_per_frame: \([0-9.]*\) clock_mhz: \([0-9]*\)/\2 ms a frame (\1 cycles at \3 MHz)/p' "$log")
        printf '%-10s %-40.40s %9s ms %9s ms %9s ms   %s\n' "$d" "$r" "$first" "${warm:--}" \
            "${per:--}" "${modeled:--}"
        rendered="$rendered $d"
    else
        printf '%-10s FAILED: %s\n' "$d" "$(tail -n 1 "$log")"
        status=1
    fi
done

case " $rendered " in *" $ref "*) ;; *)
    echo; echo "demo.sh: no $ref image to compare with"; exit 1 ;;
esac
for d in $rendered; do
    [ "$d" = "$ref" ] && continue
    echo
    echo "== $d vs $ref   (heat map: $out/$d-vs-$ref.heat.png)"
    "$compare" "$out/$d.png" "$out/$ref.png" --heatmap "$out/$d-vs-$ref.heat.png" |
        grep -v '^heat map:' | sed 's/^/   /'
    "$compare" "$out/$d.png" "$out/$ref.png" --format=kv >"$out/$d-vs-$ref.kv"
done
echo
echo "How to read this: docs/demo.md"
exit $status
