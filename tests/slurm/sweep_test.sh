#!/usr/bin/env bash
# The Slurm test: a throwaway single-node Slurm cluster on this machine (slurm-cluster), and a real
# sweep submitted through sbatch by `tandem bench --slurm` (a job array of shards and a merge job)
# in which one shard's task fails: the merge job re-submits it (and reports what there is when it
# fails again), then the same command, the fault repaired, submits that shard alone, keeping the
# others' runs. The merged results must equal those of `tandem bench` run here on the same
# experiment: the same runs and the same report apart from timings.
#
# Usage: sweep_test.sh TANDEM_BIN   (exit 0 pass, 1 fail, 77 skip: Slurm is not installed)
set -euo pipefail
tandem="$(realpath "$1")"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
python=/usr/bin/python3
[ -x "$python" ] || python=python3
work="$(mktemp -d /tmp/tandem-slurm-test.XXXXXX)"

cleanup() {
  "$here/slurm-cluster" stop "$work/cluster" >/dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT

fail() {
  echo "FAIL: $*" >&2
  for f in "$work"/cluster/log/*.log "$work"/slurm-out/slurm/*.out; do
    [ -f "$f" ] && { echo "--- $f" >&2; tail -n 20 "$f" >&2; }
  done
  exit 1
}

# Waits until the cluster has no job left (the merge job and any re-submission included).
wait_for_jobs() {
  local deadline=$((SECONDS + 600))
  while [ -n "$(squeue -h 2>/dev/null)" ]; do
    [ $SECONDS -lt $deadline ] || fail "jobs still queued after 600 s: $(squeue)"
    sleep 1
  done
}

set +e
env_line="$("$here/slurm-cluster" start "$work/cluster")"
code=$?
set -e
if [ $code -eq 77 ]; then
  echo "SKIP: Slurm (slurm-wlm, munge) is not installed: scripts/install-deps installs it"
  exit 77
fi
[ $code -eq 0 ] || fail "the cluster did not start"
eval "$env_line"
echo "cluster up: $SLURM_CONF"

cp "$here/sweep.toml" "$work/sweep.toml"
"$tandem" bench "$work/sweep.toml" --out "$work/local" --jobs 2 --quiet >/dev/null

# Round 1: shard 2 of 3 cannot write its runs (a folder stands where its file goes), so its task
# fails; the merge job finds its runs missing and submits it again, which fails again; the last
# merge job writes the report of the runs there are and says which shard is missing.
out="$work/slurm-out"
mkdir -p "$out/shards/shard-2-of-3.jsonl"
"$tandem" bench "$work/sweep.toml" --out "$out" --slurm --tasks 3 --retries 1 --quiet \
  | tee "$work/submit.txt"
grep -q "submitted job array .* (shards 1-3 of 3)" "$work/submit.txt" || fail "no job array"
wait_for_jobs
merges="$(cat "$out"/slurm/merge-*.out)"
grep -q "shards with runs missing: 2 of 3" <<<"$merges" || fail "the merge job did not see shard 2"
grep -q "submitted job array .* (shards 2 of 3)" <<<"$merges" || fail "shard 2 was not re-submitted"
grep -q "6 runs recorded" <<<"$merges" || fail "no report of the 6 runs of shards 1 and 3"
grep -q "cannot be opened" "$out"/slurm/shard-2-of-3-*.out || fail "shard 2 did not fail as set up"
for k in 1 3; do
  [ -s "$out/shards/shard-$k-of-3.jsonl" ] || fail "shard $k of 3 wrote no runs"
done
before="$(cat "$out/shards/shard-1-of-3.jsonl" "$out/shards/shard-3-of-3.jsonl" | md5sum)"

# Round 2: the fault repaired, the same command submits shard 2 alone; the others' runs are kept.
rmdir "$out/shards/shard-2-of-3.jsonl"
"$tandem" bench "$work/sweep.toml" --out "$out" --slurm --tasks 3 --quiet | tee "$work/again.txt"
grep -q "(shards 2 of 3)" "$work/again.txt" || fail "not shard 2 alone was submitted again"
wait_for_jobs
after="$(cat "$out/shards/shard-1-of-3.jsonl" "$out/shards/shard-3-of-3.jsonl" | md5sum)"
[ "$before" = "$after" ] || fail "shards 1 or 3 ran again"
"$python" "$here/compare_results.py" "$out" "$work/local" || fail "the cluster's results differ"
echo "PASS: a sweep through sbatch, with a failed shard re-submitted, equals the local one"
