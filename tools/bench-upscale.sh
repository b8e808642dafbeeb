#!/bin/bash
# The gather-heavy benchmark: tests/e2e/e2e-upscale (debanding, then polar
# EWA through 27 textureGatherOffset calls a pixel) at a video's scale,
# 180x180 to 720x720 by default, through fixpipe, softpipe and llvmpipe in
# one run: ms per frame in the steady state (the mean of the frames after
# the first --warmup, glFinish after each), the ratio to llvmpipe, the
# warm-up frames' time (compilation, and the frames fixpipe still
# interprets a shader for before it is hot: docs/jit.md), and the last
# frame's error against llvmpipe.  A benchmark, not a test: it never fails
# on a number.
#
#   tools/bench-upscale.sh [--size N] [--src N] [--frames N] [--warmup N]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
size=720 src=180 frames=24 warmup=4
while [ $# -gt 0 ]; do
    case $1 in
    --size) size=$2; shift 2 ;;
    --src) src=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --warmup) warmup=$2; shift 2 ;;
    *) echo "usage: tools/bench-upscale.sh [--size N] [--src N] [--frames N] [--warmup N]" >&2; exit 2 ;;
    esac
done
bin=$root/build/std
out=$root/out/bench-upscale
mkdir -p "$out"
declare -A ms wu
for d in llvmpipe fixpipe softpipe; do
    FIXPIPE_STATS=1 "$root/fixpipe" run --no-xvfb --driver $d -- "$bin/tests/e2e/e2e-upscale" \
        --size "$size" --src "$src" --frames "$frames" --warmup "$warmup" -o "$out/$d.png" \
        > "$out/$d.log" 2>&1
    ms[$d]=$(sed -n 's/.*ms_per_frame=\([0-9.]*\).*/\1/p' "$out/$d.log")
    wu[$d]=$(sed -n 's/.*warmup_ms=\([0-9.]*\).*/\1/p' "$out/$d.log")
done
echo "e2e-upscale ${src}x${src} -> ${size}x${size}, $frames frames, the first $warmup the warm-up ($(date -u +%Y-%m-%d), $(nproc) cores)"
echo
echo "| driver | ms per frame | x llvmpipe | warm-up ms | PSNR vs llvmpipe | mean error |"
echo "|---|---:|---:|---:|---:|---:|"
for d in llvmpipe fixpipe softpipe; do
    kv=$("$bin/tools/fp-compare" --format=kv "$out/$d.png" "$out/llvmpipe.png" 2>/dev/null || true)
    psnr=$(sed -n 's/^psnr=//p' <<<"$kv") mean=$(sed -n 's/^mean_err=//p' <<<"$kv")
    ratio=$(awk -v a="${ms[$d]}" -v b="${ms[llvmpipe]}" 'BEGIN { printf "%.2f", a / b }')
    echo "| $d | ${ms[$d]} | $ratio | ${wu[$d]} | $psnr | $mean |"
done
grep -h "fragment shaders\|gathers in compiled code" "$out/fixpipe.log" | sed 's/^ */fixpipe: /'
