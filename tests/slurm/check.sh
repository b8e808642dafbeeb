#!/bin/sh
# Campaigns through a real Slurm: a one-node cluster of the test's own (tests/slurm/cluster.sh,
# the machine's cores) runs
#   ./fixpipe piglit smoke --slurm --nodes 2 --wait: the same per-test results and verdict
#     as the local run of the list;
#   ./fixpipe sweep --grid quick --traces short --slurm --nodes 2 --wait: the same sweep.csv
#     as the local sweep apart from the run times;
#   a shard that dies (the fake piglit kills its runner): the merge does not run, the report
#     fails and names the shard and its Slurm state; nothing is merged;
#   a shard cancelled with scancel while it runs: the same;
# and the daemons it started are stopped.  Needs root, slurm-wlm and munge (./fixpipe setup).
# Each --wait is bounded (timeout): a cluster that stops scheduling fails the check, not hangs it.
# One line per check, then "N passed, N failed"; exit 1 on a failure.
checks=slurm
. "$(dirname "$0")/../e2e/checks.sh"
fixpipe=$root/fixpipe
cluster=$out/cluster

stop_cluster() { "$here/cluster.sh" stop "$cluster" || true; }
if ! "$here/cluster.sh" start "$cluster" > "$out/cluster.log" 2>&1; then
    fail "a one-node Slurm cluster starts: $(tail -n 3 "$out/cluster.log" | tr '\n' ' ')"
    stop_cluster
    checks_end
    exit 1
fi
trap stop_cluster EXIT
export SLURM_CONF=$cluster/slurm.conf
pass "a one-node Slurm cluster starts ($(sinfo -h -o '%D node, %c CPUs, partition %P'))"

# ---------------------------------------------------------------- piglit
"$fixpipe" piglit smoke --driver fixpipe --out "$out/piglit-local" > "$out/piglit-local.log" 2>&1
local_rc=$?
timeout 900 "$fixpipe" piglit smoke --driver fixpipe --slurm --nodes 2 --wait --out "$out/piglit-slurm" \
    > "$out/piglit-slurm.log" 2>&1
slurm_rc=$?
cat "$out/piglit-slurm.log"
same=$(/usr/bin/python3 - "$out/piglit-local/fixpipe-smoke/summary.json" \
    "$out/piglit-slurm/fixpipe-smoke/summary.json" <<'PY'
import json, sys
try:
    a, b = (json.load(open(p)) for p in sys.argv[1:])
except (OSError, ValueError) as e:
    print(f"no summary: {e}")
    sys.exit()
# a listed flake may come out either way: its status (flake) is what must agree
res = lambda s: {n: (t["status"], None if t["status"] == "flake" else t["result"])
                 for n, t in s["tests"].items()}
ra, rb = res(a), res(b)
diff = sorted(n for n in set(ra) | set(rb) if ra.get(n) != rb.get(n))
if diff:
    print(f"{len(diff)} tests differ: " + ", ".join(f"{n} {ra.get(n)} vs {rb.get(n)}" for n in diff[:5]))
elif a["expected"] != b["expected"] or b["shard"] != [0, 2]:
    print(f"tallies differ: {a['expected']} vs {b['expected']}, shard {b['shard']}")
else:
    print(f"same {len(ra)}")
PY
)
case $same in
"same "*) if [ "$local_rc" = "$slurm_rc" ] && grep -q "piglit-smoke-fixpipe: .* passed, .* failed" "$out/piglit-slurm.log"; then
        pass "piglit smoke through Slurm (2 shards): the local run's results for all ${same#same } tests, exit $slurm_rc"
    else
        fail "piglit smoke: exit $slurm_rc through Slurm, $local_rc locally, or no verdict printed"
    fi ;;
*) fail "piglit smoke through Slurm against the local run: $same (logs $out/piglit-*.log)" ;;
esac

# ---------------------------------------------------------------- sweep
"$fixpipe" sweep --grid quick --traces short --no-docs --out "$out/sweep-local" \
    > "$out/sweep-local.log" 2>&1
local_rc=$?
timeout 900 "$fixpipe" sweep --grid quick --traces short --no-docs --out "$out/sweep-slurm" --slurm \
    --nodes 2 --wait > "$out/sweep-slurm.log" 2>&1
slurm_rc=$?
tail -n 4 "$out/sweep-slurm.log"
same=$(/usr/bin/python3 - "$out/sweep-local/sweep.csv" "$out/sweep-slurm/sweep.csv" <<'PY'
import csv, sys
TIMES = ("run_time_s", "trace_time_s", "persp_time_s")
try:
    a, b = (list(csv.DictReader(open(p))) for p in sys.argv[1:])
except OSError as e:
    print(f"no CSV: {e}")
    sys.exit()
if not a or list(a[0]) != list(b[0] if b else []):
    print(f"columns differ or no rows: {len(a)} and {len(b)} rows")
    sys.exit()
strip = lambda rows: [{k: v for k, v in r.items() if k not in TIMES} for r in rows]
sa, sb = strip(a), strip(b)
if sa != sb:
    d = [(x["setting"], k, x[k], y.get(k)) for x, y in zip(sa, sb) for k in x if x[k] != y.get(k)]
    print(f"{len(d) or 'row count'} figures differ: {d[:4]}")
else:
    print(f"same {len(a)}")
PY
)
case $same in
"same "*) if [ "$local_rc" = 0 ] && [ "$slurm_rc" = 0 ] && [ -s "$out/sweep-slurm/pareto.png" ]; then
        pass "sweep --grid quick through Slurm (2 shards): the local sweep.csv apart from run times (${same#same } rows), its charts"
    else
        fail "sweep: exit $slurm_rc through Slurm, $local_rc locally, or no chart"
    fi ;;
*) fail "sweep through Slurm against the local run: $same (logs $out/sweep-*.log)" ;;
esac

# ---------------------------------------------------------------- a shard that dies
fake() { # the runner with the fake piglit (no GL) on a tiny list
    FIXPIPE_PIGLIT=$root/tests/harness/fake-piglit FIXPIPE_PIGLIT_DIR=$out/no-piglit \
        FIXPIPE_PIGLIT_EXPECTATIONS=$out/exp "$@"
}
mkdir -p "$out/exp"
: > "$out/exp/fixpipe-fails.txt"
printf 'fake@a@pass-1\nfake@a@pass-2\nfake@b@pass-3\nfake@c@die-here\nfake@d@pass-4\nfake@e@pass-5\n' \
    > "$out/dies.txt"
# sorted, round-robin over 3: fake@c@die-here is the 4th name, in shard 1
fake timeout 300 "$fixpipe" piglit "$out/dies.txt" --slurm --nodes 3 --wait --out "$out/dies" \
    > "$out/dies.log" 2>&1
rc=$?
cat "$out/dies.log"
if [ "$rc" = 1 ] && grep -q "shard 1/3: .*FAILED" "$out/dies.log" \
        && [ "$(grep -c '^  shard ' "$out/dies.log")" = 1 ] \
        && grep -q "merge: 0 passed, 1 failed" "$out/dies.log" \
        && [ ! -e "$out/dies/fixpipe-dies/summary.json" ] \
        && ! grep -q "piglit-dies-fixpipe: [0-9]* passed" "$out/dies.log"; then
    pass "a shard that dies: the merge fails and names it (shard 1/3, FAILED), nothing merged"
else
    fail "a shard that dies: exit $rc, the report does not name shard 1/3 alone or a merge was written ($out/dies.log)"
fi

# ---------------------------------------------------------------- a cancelled shard
# one shard at a time on the one node (--exclusive): shard 1 is cancelled while it runs
printf 'fake@a@pass-1\nfake@b@pass-2\n' > "$out/slow.txt"
FAKE_PIGLIT_DELAY=15 fake "$fixpipe" piglit "$out/slow.txt" --slurm --nodes 2 --out "$out/slow" \
    > "$out/slow.log" 2>&1
array=$(sed -n 's/.*Slurm array job \([0-9]*\) .*/\1/p' "$out/slow.log")
n=0
until [ -e "$out/slow/fixpipe-slow-s1of2/shard-started.json" ] || [ $n -ge 600 ]; do
    sleep 0.1; n=$((n + 1))
done
scancel "${array}_1" 2>>"$out/slow.log"
# shard 2 runs its 15 s; then the report job
n=0
until grep -qs "merge: " "$out/slow/slurm/report.log" || [ $n -ge 180 ]; do
    sleep 1; n=$((n + 1))
done
cat "$out/slow/slurm/report.log" 2>/dev/null
if grep -q "shard 1/2: .*CANCELLED" "$out/slow/slurm/report.log" 2>/dev/null \
        && [ ! -s "$out/slow/slurm/merge.log" ] && [ ! -e "$out/slow/fixpipe-slow/summary.json" ]; then
    pass "a shard cancelled while it runs: the report names it (shard 1/2, CANCELLED), the merge never ran"
else
    fail "a cancelled shard: the report ($out/slow/slurm/report.log) does not name shard 1/2 as cancelled, or a merge ran"
fi

# ---------------------------------------------------------------- stop
ctld=$(cat "$cluster/slurmctld.pid" 2>/dev/null) slurmd=$(cat "$cluster/slurmd.pid" 2>/dev/null)
munged=$(cat "$cluster/munged.pid" 2>/dev/null)
trap - EXIT
stop_cluster
if [ -n "$ctld" ] && [ -n "$slurmd" ] && [ -n "$munged" ] && ! kill -0 "$ctld" 2>/dev/null \
        && ! kill -0 "$slurmd" 2>/dev/null && ! kill -0 "$munged" 2>/dev/null; then
    pass "the daemons it started are stopped (slurmctld $ctld, slurmd $slurmd, munged $munged)"
else
    fail "slurmctld ($ctld), slurmd ($slurmd) or munged ($munged) still runs after stop"
fi
checks_end
