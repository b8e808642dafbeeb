#!/bin/bash
# Speed against error, all drivers in one run on this machine:
#   glmark2-es2 scenes (frames per second, under a virtual X server) and the
#   bundled demo (ms per frame, error against llvmpipe), for fixpipe (each
#   profile), softpipe (our build, same Mesa) and llvmpipe (Debian's).
# Prints a markdown table; with --doc, rewrites the table in docs/benchmarks.md
# between its markers.  A benchmark, not a test: it never fails on a number.
#
#   tools/bench.sh [--doc] [--seconds S] [--size WxH]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
doc=0 secs=5 size=400x300
while [ $# -gt 0 ]; do
    case $1 in
    --doc) doc=1; shift ;;
    --seconds) secs=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    *) echo "usage: tools/bench.sh [--doc] [--seconds S] [--size WxH]" >&2; exit 2 ;;
    esac
done
fp=$root/fixpipe
bin=$root/build/std/tools
out=$root/out/bench
mkdir -p "$out"
scenes=(build texture shading bump effect2d)
# name | launcher options | environment of the program
configs=("fixpipe seed|--driver fixpipe --profile seed|"
         "fixpipe wide|--driver fixpipe --profile wide|"
         "fixpipe seed float-tex|--driver fixpipe --profile seed|FIXPIPE_TEXFMT=float"
         "softpipe|--driver softpipe|"
         "llvmpipe|--driver llvmpipe|")

glmark_args=(-s "$size")
for s in "${scenes[@]}"; do glmark_args+=(-b "$s:duration=$secs"); done

declare -A fps ms psnr mean
for c in "${configs[@]}"; do
    IFS='|' read -r name opts envs <<<"$c"
    key=${name// /-}
    # shellcheck disable=SC2086
    "$fp" run --xvfb $opts -- env $envs glmark2-es2 "${glmark_args[@]}" > "$out/$key.glmark.log" 2>&1 || true
    for s in "${scenes[@]}"; do
        v=$(sed -n "s/^\[$s\] .*FPS: \([0-9]*\).*/\1/p" "$out/$key.glmark.log" | head -1)
        fps[$key,$s]=${v:-n/a}
    done
    # shellcheck disable=SC2086
    "$fp" run --no-xvfb $opts -- env $envs "$bin/fp-demo" --scene all --frames 30 -o "$out/$key.demo.png" \
        > "$out/$key.demo.log" 2>&1 || true
    ms[$key]=$(sed -n 's/.*ms_per_frame: \([0-9.]*\).*/\1/p' "$out/$key.demo.log")
done
for c in "${configs[@]}"; do
    name=${c%%|*}; key=${name// /-}
    kv=$("$bin/fp-compare" "$out/$key.demo.png" "$out/llvmpipe.demo.png" --format=kv 2>/dev/null || true)
    psnr[$key]=$(sed -n 's/^psnr=//p' <<<"$kv")
    mean[$key]=$(sed -n 's/^mean_err=//p' <<<"$kv")
done

ratio() {   # a / b with two decimals, or n/a
    awk -v a="$1" -v b="$2" 'BEGIN { if (a+0 > 0 && b+0 > 0) printf "%.2f", a / b; else print "n/a" }'
}

{
    echo "Measured $(date -u +%Y-%m-%d) on $(nproc) cores: \`tools/bench.sh --seconds $secs --size $size\`."
    echo
    printf '| glmark2-es2 %s, fps |' "$size"
    for c in "${configs[@]}"; do printf ' %s |' "${c%%|*}"; done
    echo " fixpipe seed ÷ llvmpipe | fixpipe seed ÷ softpipe |"
    printf '|---|'; for _ in "${configs[@]}"; do printf -- '---:|'; done; printf -- '---:|---:|\n'
    for s in "${scenes[@]}"; do
        printf '| %s |' "$s"
        for c in "${configs[@]}"; do n=${c%%|*}; printf ' %s |' "${fps[${n// /-},$s]}"; done
        printf ' %s | %s |\n' "$(ratio "${fps[fixpipe-seed,$s]}" "${fps[llvmpipe,$s]}")" \
            "$(ratio "${fps[fixpipe-seed,$s]}" "${fps[softpipe,$s]}")"
    done
    echo
    echo "| demo 512×512 (\`fp-demo --scene all\`) | ms/frame | mean error vs llvmpipe (0–255) | PSNR vs llvmpipe (dB) |"
    echo "|---|---:|---:|---:|"
    for c in "${configs[@]}"; do
        n=${c%%|*}; k=${n// /-}
        printf '| %s | %s | %s | %s |\n' "$n" "${ms[$k]:-n/a}" "${mean[$k]:-n/a}" "${psnr[$k]:-n/a}"
    done
} | tee "$out/table.md"

# Run time against error: the demo's ms/frame and its mean error against
# llvmpipe, a row per configuration (empty where not measured).
{
    printf 'name\tms_per_frame\tmean_error\n'
    for c in "${configs[@]}"; do
        n=${c%%|*}; k=${n// /-}
        printf '%s\t%s\t%s\n' "$n" "${ms[$k]:-}" "${mean[$k]:-}"
    done
} > "$out/time-vs-error.tsv"
/usr/bin/python3 "$root/tools/bench-chart" "$out/time-vs-error.tsv" "$out/time-vs-error.png" ||
    echo "bench: no chart (bench-chart failed)" >&2

if [ $doc = 1 ]; then
    mkdir -p "$root/docs/img"
    [ -f "$out/time-vs-error.png" ] && cp "$out/time-vs-error.png" "$root/docs/img/bench-time-vs-error.png"
    f=$root/docs/benchmarks.md
    awk -v table="$out/table.md" '
        /<!-- bench:begin -->/ { print; while ((getline l < table) > 0) print l; skip = 1; next }
        /<!-- bench:end -->/ { skip = 0 }
        !skip' "$f" > "$f.tmp" && mv "$f.tmp" "$f"
    echo "bench: table written to docs/benchmarks.md"
fi
