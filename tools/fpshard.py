"""Shards of a campaign: which shard a run is, and the files that say what a shard did.

A campaign command (`./fixpipe piglit`, `deqp`, `trace compare`, `sweep`, `stress`, `fuzz`)
is one shard I of N when it is given `--shard I/N`, or else when it runs as a task of a
Slurm job array (SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_MIN, SLURM_ARRAY_TASK_COUNT) or in
one of GitLab CI's `parallel:` jobs (CI_NODE_INDEX, 1-based, and CI_NODE_TOTAL), in that
order.  A shard writes into its own directory below the campaign's result directory DIR:

  DIR/campaign.json          the campaign (command and its key) and N: a second campaign
                             writing DIR is refused
  SHARD/shard-started.json   where and when the shard began
  SHARD/shard.json           written last, when the shard's results are complete: its exit
                             status and what the merge needs

`./fixpipe merge DIR` (tools/fp-merge) merges the shards once every one has its shard.json.
docs/cluster.md describes it all.
"""
import fcntl
import json
import os
import re
import socket
import sys
import time

FORMAT = "fixpipe-shard/1"
CAMPAIGN_FORMAT = "fixpipe-campaign/1"
_locks = []  # the flocks a shard holds while it runs


def die(msg, status=2):
    print(f"fixpipe: {msg}", file=sys.stderr)
    sys.exit(status)


def parse(text, what="--shard"):
    m = re.fullmatch(r"\s*(\d+)\s*/\s*(\d+)\s*", text or "")
    if not m or not 1 <= int(m.group(1)) <= int(m.group(2)):
        die(f"{what} wants I/N with 1 <= I <= N, got {text!r}")
    return int(m.group(1)), int(m.group(2))


def from_env(env=None):
    """(I, N, source) from Slurm's or GitLab's variables, or None."""
    env = os.environ if env is None else env
    if env.get("SLURM_ARRAY_TASK_ID") not in (None, ""):
        tid, count = env.get("SLURM_ARRAY_TASK_ID"), env.get("SLURM_ARRAY_TASK_COUNT")
        first, step = env.get("SLURM_ARRAY_TASK_MIN", "1"), env.get("SLURM_ARRAY_TASK_STEP", "1")
        if not all(v and v.isdigit() for v in (tid, count, first, step)) or int(step) < 1:
            die("SLURM_ARRAY_TASK_ID/_MIN/_STEP/_COUNT are not whole numbers: "
                f"{tid!r}, {first!r}, {step!r}, {count!r}")
        i = (int(tid) - int(first)) // int(step) + 1
        i, n = parse(f"{i}/{count}", "SLURM_ARRAY_TASK_ID of SLURM_ARRAY_TASK_COUNT")
        return i, n, "Slurm"
    if env.get("CI_NODE_TOTAL") not in (None, ""):
        i, n = parse(f"{env.get('CI_NODE_INDEX', '')}/{env['CI_NODE_TOTAL']}",
                     "CI_NODE_INDEX/CI_NODE_TOTAL")
        return i, n, "GitLab CI"
    return None


def resolve(cli=None, env=None):
    """(I, N, sharded): --shard I/N first, then the environment, else (1, 1, False)."""
    if cli:
        i, n = parse(cli) if isinstance(cli, str) else cli
        return i, n, True
    e = from_env(env)
    if e:
        return e[0], e[1], True
    return 1, 1, False


def split(items, i, n):
    """Round-robin over the items in their given order: item k goes to shard k mod N + 1.
    Every item is in exactly one shard, sizes differ by at most one."""
    return [t for k, t in enumerate(items) if k % n == i - 1]


def _write_json(path, data):
    tmp = f"{path}.tmp{os.getpid()}"
    with open(tmp, "w", encoding="utf-8") as f:
        json.dump(data, f, indent=1, sort_keys=True)
        f.write("\n")
    os.replace(tmp, path)


def claim(result_dir, shard_dir, campaign, key, i, n):
    """Before a shard writes anything: DIR's campaign must be this one (or none yet), DIR
    must hold no merged run, and no other process may be writing this shard.  Removes the
    shard's old completion mark; writes shard-started.json."""
    os.makedirs(result_dir, exist_ok=True)
    with open(os.path.join(result_dir, ".campaign.lock"), "w") as lk:
        fcntl.flock(lk, fcntl.LOCK_EX)
        path = os.path.join(result_dir, "campaign.json")
        want = {"campaign": campaign, "key": key, "shards": n}
        if os.path.exists(path):
            try:
                with open(path, encoding="utf-8") as f:
                    have = json.load(f)
            except (OSError, ValueError) as e:
                die(f"{path}: {e}")
            if have.get("key") is None and have.get("campaign") == campaign \
                    and have.get("shards") == n:
                # submitted by --slurm, which knows the command, not yet its key
                have["key"] = key
                _write_json(path, have)
            if {k: have.get(k) for k in want} != want:
                die(f"{result_dir} holds another campaign ({describe(have)}), not "
                    f"{describe(want)}: give each campaign its own result directory")
            if have.get("merged"):
                die(f"{result_dir} holds a complete merged run ({have['merged']}): its shards "
                    "are not written again; give the new run another result directory")
        else:
            _write_json(path, dict(want, format=CAMPAIGN_FORMAT,
                                   created=time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())))
    os.makedirs(shard_dir, exist_ok=True)
    lock = open(os.path.join(shard_dir, ".shard.lock"), "a+")
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        lock.seek(0)
        die(f"shard {i}/{n} of {describe(want)} is being written by another process "
            f"({lock.read().strip() or 'unknown'}) in {shard_dir}")
    lock.seek(0)
    lock.truncate()
    lock.write(f"{socket.gethostname()} pid {os.getpid()}\n")
    lock.flush()
    _locks.append(lock)
    for stale in ("shard.json",):
        if os.path.exists(os.path.join(shard_dir, stale)):
            os.remove(os.path.join(shard_dir, stale))
    _write_json(os.path.join(shard_dir, "shard-started.json"), {
        "format": FORMAT, "campaign": campaign, "key": key, "shard": [i, n],
        "host": socket.gethostname(), "pid": os.getpid(),
        "slurm_job": slurm_job_id(),
        "started": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())})


def update_campaign(result_dir, **fields):
    """Sets fields of DIR/campaign.json under its lock (shards may be filling in its key)."""
    with open(os.path.join(result_dir, ".campaign.lock"), "w") as lk:
        fcntl.flock(lk, fcntl.LOCK_EX)
        path = os.path.join(result_dir, "campaign.json")
        with open(path, encoding="utf-8") as f:
            have = json.load(f)
        have.update(fields)
        _write_json(path, have)


def slurm_job_id():
    j, t = os.environ.get("SLURM_ARRAY_JOB_ID"), os.environ.get("SLURM_ARRAY_TASK_ID")
    return f"{j}_{t}" if j and t else os.environ.get("SLURM_JOB_ID")


def done(shard_dir, campaign, key, i, n, status, **extra):
    """The shard's results are complete: its mark, written last."""
    _write_json(os.path.join(shard_dir, "shard.json"), dict(
        extra, format=FORMAT, campaign=campaign, key=key, shard=[i, n], exit_status=status,
        host=socket.gethostname(), slurm_job=slurm_job_id(),
        finished=time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())))


def describe(c):
    key = c.get("key") or {}
    words = " ".join(f"{k}={v}" if not isinstance(v, list) else f"{k}={','.join(map(str, v))}"
                     for k, v in sorted(key.items()) if k != "out" and v not in (None, "", []))
    return f"{c.get('campaign')} {words}".strip() + f", {c.get('shards')} shards"


def main(argv):
    """`fpshard.py resolve [I/N]`: prints 'I N sharded' for the launcher's shell commands."""
    if argv[:1] == ["resolve"] and len(argv) <= 2:
        i, n, sharded = resolve(argv[1] if len(argv) == 2 else None)
        print(i, n, int(sharded))
        return 0
    if argv[:1] == ["claim"] and len(argv) == 7:
        # claim RESULT_DIR SHARD_DIR CAMPAIGN KEY_JSON I N (the lock lasts as long as the
        # caller's process when it holds fd 9 open on SHARD_DIR/.shard.lock itself)
        claim(argv[1], argv[2], argv[3], json.loads(argv[4]), int(argv[5]), int(argv[6]))
        return 0
    if argv[:1] == ["done"] and len(argv) >= 8:
        extra = json.loads(argv[7]) if len(argv) > 7 else {}
        done(argv[1], argv[2], json.loads(argv[3]), int(argv[4]), int(argv[5]), int(argv[6]),
             **extra)
        return 0
    print("usage: fpshard.py resolve [I/N] | claim DIR SHARD_DIR CAMPAIGN KEY I N | "
          "done SHARD_DIR CAMPAIGN KEY I N STATUS EXTRA_JSON", file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
