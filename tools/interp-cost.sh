#!/bin/bash
# The seeds' interpolator cost figures (docs/interp-modes.md): runs
# tools/fp-interp-cost (the model alone, no GL) and draws its CSVs with
# matplotlib (tools/interp-cost-charts.py) into docs/img/interp-cost.png
# and docs/img/interp-cores.png.
#   tools/interp-cost.sh [OUTDIR] [fp-interp-cost options]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/out/interp}
shift || true
mkdir -p "$out"
"$root/build/std/tools/fp-interp-cost" "$out" "$@" | tee "$out/tables.txt"
/usr/bin/python3 "$root/tools/interp-cost-charts.py" "$out" "$root/docs/img"
echo "interp-cost: docs/img/interp-cost.png, docs/img/interp-cores.png; tables in $out/tables.txt"
