"""Sessions stepped from Python, operators written in Python (journaled, and replayed by `tandem
replay`), and experiments run from Python as `tandem bench` runs them."""
import json
import os
import tempfile

import numpy as np
import pytest

import tandem

from command_line import run_cli


def test_a_planner_steps_and_its_trees_grow(cluttered):
    s = tandem.Session(cluttered, planner="birrt", seed=4)
    assert s.step() == "running" and s.steps == 1
    sizes = []
    for _ in range(5):
        s.step(40)
        trees = s.trees()
        assert len(trees) == 2
        sizes.append(sum(len(t["nodes"]) for t in trees))
        for t in trees:
            n = len(t["nodes"])
            assert t["nodes"].shape == (n, 7) and t["parents"].shape == (n,)
            assert t["parents"][0] == -1 and t["sources"][0] == "root"
            # A node's parent was added before it.
            assert np.all(t["parents"][1:] < np.arange(1, n))
        assert sizes[-1] == s.stats["nodes"]
    assert sizes == sorted(sizes) and sizes[-1] > sizes[0]
    np.testing.assert_array_equal(s.trees()[0]["nodes"][0], cluttered.start)
    np.testing.assert_array_equal(s.trees()[1]["nodes"][0], cluttered.goal)
    assert s.run() == "solved"
    assert tandem.check_path(cluttered, s.solution)["valid"]
    # The same planner, seed and thread count as tandem.plan: the same trees.
    plan = tandem.plan(cluttered, planner="birrt", seed=4, threads=1, simplify=False)
    assert s.tree_digest == plan["tree_digest"]
    assert s.stats["iterations"] == plan["iterations"]


def test_a_simulated_operator_gives_the_run_of_tandem_plan(cluttered):
    s = tandem.Session(cluttered, planner="interactive-contact", seed=3, operator="experienced",
                       alpha=0.3)
    assert s.run() == "solved"
    assert s.stats["nodes_by_source"]["operator"] > 0
    plan = tandem.plan(cluttered, planner="interactive-contact", seed=3, alpha=0.3,
                       operator="experienced")
    assert s.tree_digest == plan["tree_digest"]


class TowardTheGoal:
    """A scripted operator: from where it held the part last, a share of the way to the goal (in
    the goal's orientation), or, when the part is in contact, a step along the tangent plane."""

    def __init__(self, problem):
        self.problem = problem
        self.views = []

    def __call__(self, view):
        self.views.append(view)
        prev = view["previous"]
        q = (prev["q_device"] if prev is not None else self.problem.start).copy()
        step = 0.02 * (self.problem.goal[:3] - q[:3])
        frame = prev["contact_frame"] if prev is not None else None
        if frame is not None and frame["distance"] < 0.01:
            n = np.asarray(frame["normal"])
            step -= min(0.0, step @ n) * n  # do not push into the surface
        q[:3] += step
        q[3:] = self.problem.goal[3:]
        return q


def test_a_python_operator_drives_a_journaled_session_that_tandem_replay_reproduces(cluttered):
    op = TowardTheGoal(cluttered)
    with tempfile.TemporaryDirectory() as d:
        journal = os.path.join(d, "session.jsonl")
        with tandem.Session("cluttered-1", planner="interactive-contact", seed=8, operator=op,
                            journal=journal, digest_every=1000, alpha=0.5, time_limit=30,
                            operator_period=5) as s:
            assert s.step(200) == "running"
            state = s.operator_state
            assert state is not None and state["q_device"].shape == (7,)
            assert state["nearest"]["obstacle"] in cluttered.obstacles
            assert s.run() == "solved"
            digest, steps = s.tree_digest, s.steps
        # Called at most once per 5 iterations (when the planner asks), in operator time (ticks),
        # shown the trees and its previous state.
        times = [v["time"] for v in op.views]
        assert len(times) > 100 and all(t % 5 == 0 for t in times)
        assert times == sorted(set(times))
        assert op.views[0]["previous"] is None and op.views[-1]["previous"] is not None
        assert op.views[-1]["nodes"] > op.views[1]["nodes"]
        assert s.stats["nodes_by_source"]["operator"] > 0
        assert tandem.check_path(cluttered, s.solution)["valid"]
        replay = run_cli("replay", journal)
        assert replay.returncode == 0, replay.stderr
        assert f"replayed {steps} steps" in replay.stdout
        assert digest in replay.stdout and "identical" in replay.stdout
        header = json.loads(open(journal).readline())
        assert header["problem"] == "cluttered-1"
        assert header["operator"].startswith("Python operator")


def test_a_failing_operator_ends_the_session_with_its_exception(cluttered):
    def broken(view):
        if view["iteration"] > 30:
            raise RuntimeError("the policy fell over")
        return cluttered.start

    with tempfile.TemporaryDirectory() as d:
        journal = os.path.join(d, "s.jsonl")
        s = tandem.Session(cluttered, planner="interactive", seed=1, operator=broken,
                           journal=journal)
        with pytest.raises(RuntimeError, match="fell over"):
            s.run()
        with pytest.raises(tandem.InputError, match="operator raised"):
            s.step()
        # The journal has what was recorded, and its end.
        assert json.loads(open(journal).read().splitlines()[-1])["end"] == "running"

    def wrong_shape(view):
        return np.zeros(4)

    with pytest.raises(tandem.InputError, match="operator's q_device"):
        tandem.Session(cluttered, planner="interactive", seed=1, operator=wrong_shape).step(50)
    with pytest.raises(tandem.InputError, match="operator"):
        tandem.Session(cluttered, planner="interactive", operator=42)
    with pytest.raises(tandem.InputError, match="plans alone"):
        tandem.Session(cluttered, planner="birrt", operator=lambda v: cluttered.start)
    with pytest.raises(tandem.InputError, match="journal"):
        tandem.Session(cluttered, planner="birrt", journal="/tmp/never.jsonl")


EXPERIMENT = """name = "py"
problem = "cluttered-1"
seeds = 2
time_limit = 20
[[sweep]]
mode = ["birrt"]
range = [0.3, 0.6]
"""


def test_an_experiment_runs_from_python_as_tandem_bench_runs_it():
    with tempfile.TemporaryDirectory() as d:
        exp = os.path.join(d, "py.toml")
        with open(exp, "w") as f:
            f.write(EXPERIMENT)
        out = os.path.join(d, "out")
        result = tandem.bench(exp, out=out, jobs=2)
        assert result["name"] == "py" and result["planned"] == 4 and result["ran"] == 4
        records = result["records"]
        assert [r["seed"] for r in records] == [1, 2, 1, 2]
        assert all(r["solved"] and r["path_valid"] for r in records)
        assert {r["params"]["range"] for r in records} == {"0.3", "0.6"}
        assert os.path.exists(result["report"]) and os.path.exists(os.path.join(out, "ompl.log"))
        assert sorted(r["tree_digest"] for r in tandem.read_runs(result["runs"])) == sorted(
            r["tree_digest"] for r in records)
        # Again: nothing left to run. And the command line reads the same runs.
        assert tandem.bench(exp, out=out)["ran"] == 0
        cli = run_cli("bench", exp, "--out", out, "--report-only")
        assert cli.returncode == 0 and "4 runs recorded" in cli.stdout
        # A shard from Python, merged by the command line.
        sharded = os.path.join(d, "sharded")
        one = tandem.bench(exp, out=sharded, shard="1/2")
        two = tandem.bench(exp, out=sharded, shard="2/2")
        assert one["report"] is None and len(one["records"]) + len(two["records"]) == 4
        merged = run_cli("bench", exp, "--out", sharded, "--merge")
        assert merged.returncode == 0, merged.stdout + merged.stderr
        digests = {(r["config"], r["seed"]): r["tree_digest"] for r in records}
        for r in tandem.read_runs(os.path.join(sharded, "runs.jsonl")):
            assert digests[(r["config"], r["seed"])] == r["tree_digest"]
        with pytest.raises(tandem.InputError, match="shard"):
            tandem.bench(exp, out=sharded, shard="3/2")


def test_a_python_operator_drives_a_live_session_that_tandem_replay_reproduces(cluttered):
    op = TowardTheGoal(cluttered)
    with tempfile.TemporaryDirectory() as d:
        journal = os.path.join(d, "live.jsonl")
        r = tandem.live(cluttered, planner="interactive-contact", seed=8, operator=op,
                        journal=journal, time_limit=10, alpha=0.5, rate_hz=200)
        assert r["status"] in ("solved", "timeout") and r["steps"] > 0
        # On the wall clock: seconds, at about rate_hz.
        times = [v["time"] for v in op.views]
        assert len(times) >= 2 and times == sorted(times) and times[-1] < 11
        assert op.views[-1]["previous"] is not None
        replay = run_cli("replay", journal)
        assert replay.returncode == 0, replay.stderr
        assert r["tree_digest"] in replay.stdout and "identical" in replay.stdout
        if r["status"] == "solved":
            assert tandem.check_path(cluttered, r["solution"])["valid"]

        def lost(view):
            if view["time"] > 0.1:
                raise KeyError("lost the device")
            return cluttered.start

        with pytest.raises(KeyError, match="lost the device"):
            tandem.live(cluttered, planner="interactive", seed=1, operator=lost,
                        journal=os.path.join(d, "lost.jsonl"), time_limit=5)
    with pytest.raises(tandem.InputError, match="journal"):
        tandem.live(cluttered, planner="interactive", operator=op)
    with pytest.raises(tandem.InputError, match="rate_hz"):
        tandem.live(cluttered, planner="interactive", operator=op, journal="x.jsonl", rate_hz=0)
