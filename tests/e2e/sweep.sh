#!/bin/sh
# ./fixpipe sweep's machinery on a small grid (tools/fp-sweep --grid quick: seed and
# seed:xy=12.4) over one trace and the seed-003 scene.  Checks:
#   it runs, and its CSV has the two references, the maximal-precision model and the
#     two settings, each with every figure;
#   the comparison sees differences (softpipe against llvmpipe is not 0), and the
#     maximal model rendered a second time is identical to its first render
#     (determinism: the maximal row is that second render);
#   the measurement sees precision: seed:xy=12.4 is further from the maximal model
#     than seed is;
#   the two charts are PNG files;
#   tools/fp-plot (the figure scripts' charts) draws a PNG from its data file and
#     refuses a point outside a series.
# One line per check, then "N passed, N failed"; exit 1 on a failure.
checks=sweep
. "$(dirname "$0")/checks.sh"

if ! /usr/bin/python3 "$root/tools/fp-sweep" --grid quick --traces glmark2-build-vbo --no-docs \
        --out "$out" --build "$build" > "$out/sweep.log" 2>&1; then
    fail "fp-sweep --grid quick: $(tail -n 1 "$out/sweep.log")"
    checks_end
    exit
fi
pass "fp-sweep --grid quick ran"

# field SETTING COLUMN: one figure of the CSV
field() {
    /usr/bin/python3 - "$out/sweep.csv" "$1" "$2" <<'PY'
import csv, sys
rows = {r["setting"]: r for r in csv.DictReader(open(sys.argv[1]))}
print(rows.get(sys.argv[2], {}).get(sys.argv[3], "missing"))
PY
}

rows=$(($(wc -l < "$out/sweep.csv") - 1))
empty=$(/usr/bin/python3 - "$out/sweep.csv" <<'PY'
import csv, sys
keys = ("run_time_s", "llvm_mean", "llvm_psnr", "max_mean", "max_psnr", "persp_llvm_psnr",
        "sat_xy", "tex_flush", "watertight_holes", "watertight_twice")
print(sum(1 for r in csv.DictReader(open(sys.argv[1]))
          if r["family"] != "reference" for k in keys if r[k] == ""))
PY
)
if [ "$rows" = 5 ] && [ "$empty" = 0 ]; then
    pass "sweep.csv: llvmpipe, softpipe, maximal, seed, xy=12.4, every figure present"
else
    fail "sweep.csv: $rows rows (want 5), $empty empty figures"
fi

sp=$(field softpipe llvm_mean)
if awk -v m="$sp" 'BEGIN { exit !(m + 0 > 0) }' && [ "$(field maximal max_psnr)" = inf ]; then
    pass "softpipe against llvmpipe $sp (the comparison sees differences); the maximal model rendered twice identical"
else
    fail "softpipe against llvmpipe $sp (want > 0), the maximal model's second render $(field maximal max_psnr) dB (want inf)"
fi

s=$(field seed max_psnr) c=$(field xy=12.4 max_psnr)
if awk -v s="$s" -v c="$c" 'BEGIN { if (s == "inf") s = 1e9; exit !(c + 1 < s) }'; then
    pass "xy=12.4 is further from the maximal model ($c dB) than seed ($s dB)"
else
    fail "xy=12.4 ($c dB) is not further from the maximal model than seed ($s dB)"
fi

for f in pareto bits; do
    if [ "$(head -c 8 "$out/$f.png" 2>/dev/null | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ]; then
        pass "$f.png drawn"
    else
        fail "$f.png missing or not a PNG"
    fi
done
printf 'title t\nlogx\nlegend tl\nseries 200,40,40 line a\n1 2 one\n10 3\n' > "$out/plot.txt"
printf 'title t\n1 2\n' > "$out/bad.txt"
if "$root/tools/fp-plot" "$out/plot.txt" "$out/plot.png" --size 320x200 &&
   [ "$(head -c 4 "$out/plot.png" | od -An -tx1 | tr -d ' \n')" = 89504e47 ] &&
   ! "$root/tools/fp-plot" "$out/bad.txt" "$out/bad.png" 2>/dev/null; then
    pass "fp-plot draws a chart and refuses a point outside a series"
else
    fail "fp-plot: no PNG from a good file, or a bad file accepted"
fi
checks_end
