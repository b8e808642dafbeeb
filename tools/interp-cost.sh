#!/bin/bash
# The seeds' interpolator cost figures (docs/interp-modes.md): runs
# tools/fp-interp-cost (the model alone, no GL) and draws its CSVs with
# gnuplot into docs/img/interp-cost.png and docs/img/interp-cores.png.
#   tools/interp-cost.sh [OUTDIR] [fp-interp-cost options]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/out/interp}
shift || true
mkdir -p "$out"
"$root/build/std/tools/fp-interp-cost" "$out" "$@" | tee "$out/tables.txt"
command -v gnuplot >/dev/null || { echo "interp-cost: gnuplot not found (tools/install-deps.sh)" >&2; exit 1; }

# per mode: pixels op-per-pixel, one block a mode
for op in add mul; do
    col=$([ $op = add ] && echo 3 || echo 4)
    for m in scanline baseline barycentric vector; do
        awk -F, -v m=$m -v c=$col 'NR > 1 && $2 == m { print $1, $c }' "$out/cost.csv"
        printf '\n\n'
    done > "$out/cost-$op.dat"
done
for u in barycentric scanline; do
    awk -F, -v u=$u 'NR > 1 && $2 == u' "$out/cores.csv" | awk -F, -v u=$u '
        u == "scanline" { print $1, $4; next }
        { v[$3] = v[$3] " " $1 " " $4 "\n" } END { for (c = 1; c <= 64; c *= 2) if (c in v) printf "%s\n\n", v[c] }'
done > "$out/cores.dat"

gnuplot <<GP
set terminal pngcairo size 1100,460 font "sans,11"
set output "$root/docs/img/interp-cost.png"
set multiplot layout 1,2 title "Interpolator operations per covered pixel (Z, R, G, B registers; seed profile; fp-interp-cost)"
array T[4] = ["scan-line walk (000)", "walk per pixel (002's baseline)", "barycentric (001)", "vector (002)"]
set logscale xy
set xlabel "polygon size (pixels)"
set grid
set key top left
set xrange [350:45000]
set yrange [0.01:30000]
set title "additions"
plot for [i=0:3] "$out/cost-add.dat" index i using 1:2 with linespoints lw 2 \
     title T[i+1]
set title "multiplications"
plot for [i=0:3] "$out/cost-mul.dat" index i using 1:2 with linespoints lw 2 \
     title T[i+1]
unset multiplot
GP

gnuplot <<GP
set terminal pngcairo size 800,480 font "sans,11"
set output "$root/docs/img/interp-cores.png"
set title "Pixels per clock: seed 001's N cores against seed 000's scan-line unit (fp-interp-cost)"
set logscale x
set xlabel "polygon size (pixels)"
set ylabel "covered pixels per clock"
set grid
set key outside right
set xrange [350:45000]
plot for [i=0:6] "$out/cores.dat" index i using 1:2 with linespoints lw 2 title sprintf("%d cores (001)", 2**i), \
     "$out/cores.dat" index 7 using 1:2 with linespoints lw 3 dt 2 lc rgb "black" title "scan-line (000)"
GP
echo "interp-cost: docs/img/interp-cost.png, docs/img/interp-cores.png; tables in $out/tables.txt"
