"""The Python module against the command line: the same plan for the same seed, path checks,
collision and distance queries against known geometry, the planners' parameters, and errors that
carry tandem's message."""
import json
import os
import tempfile

import numpy as np
import pytest

import tandem

from command_line import run_cli


def test_a_problem_shows_its_name_bounds_start_goal_and_obstacles(cluttered):
    assert cluttered.name == "cluttered-1"
    assert not cluttered.planar
    assert cluttered.bounds.shape == (2, 3)
    assert np.all(cluttered.bounds[0] < cluttered.bounds[1])
    assert cluttered.start.shape == (7,) and cluttered.goal.shape == (7,)
    assert "oblique-bar" in cluttered.obstacles
    assert repr(cluttered) == "<tandem.Problem 'cluttered-1'>"
    planar = tandem.Problem("labyrinth-2d")
    assert planar.planar and planar.start.shape == (3,)


def test_plan_gives_the_command_lines_path_for_the_same_seed(cluttered):
    result = tandem.plan(cluttered, planner="birrt", seed=4, threads=1)
    assert result["solved"] and result["status"] == "solved"
    path = result["path"]
    assert path.ndim == 2 and path.shape[1] == 7 and len(path) >= 2
    np.testing.assert_array_equal(path[0], cluttered.start)
    assert tandem.check_path(cluttered, path)["valid"]
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "p.path")
        cli = run_cli("plan", "cluttered-1", "--planner", "birrt", "--seed", "4", "--threads", "1",
                      "--out", out, "--json")
        assert cli.returncode == 0, cli.stderr
        np.testing.assert_array_equal(np.loadtxt(out, ndmin=2), path)
        record = json.loads(cli.stdout)
    for key in ("iterations", "nodes", "collision_checks", "tree_digest"):
        assert result[key] == record[key], key


def test_parameters_set_by_keyword_change_the_run(cluttered):
    a = tandem.plan(cluttered, planner="birrt", seed=2, threads=1, range=0.3)
    b = tandem.plan(cluttered, planner="birrt", seed=2, threads=1, range=0.6)
    assert a["solved"] and b["solved"]
    assert a["tree_digest"] != b["tree_digest"]
    assert b["params"]["range"] == "0.6"  # as the run records give them: text


def test_check_path_finds_the_first_bad_state_or_motion(cluttered):
    start, goal = cluttered.start, cluttered.goal
    straight = tandem.check_path(cluttered, np.stack([start, goal]))
    assert not straight["valid"] and straight["motion"] and straight["index"] == 1
    assert "motion" in straight["message"]
    assert tandem.check_path(cluttered, start)["valid"]


def test_collision_and_distance_queries_one_or_a_batch(cluttered):
    c = tandem.Collision(cluttered)
    assert c.is_free(cluttered.start) is True
    batch = np.stack([cluttered.start, cluttered.goal, cluttered.start])
    free = c.is_free(batch)
    assert free.dtype == np.bool_ and free.tolist() == [True, True, True]
    near = c.nearest(cluttered.start)
    assert near["distance"] > 0 and near["obstacle"] in cluttered.obstacles
    assert len(near["point_on_object"]) == 3
    d, names = c.distances(batch)
    assert d.shape == (3,) and d[0] == pytest.approx(near["distance"]) and names[0] == near["obstacle"]
    # The part moved into the floor collides, and its distance is 0.
    sunk = cluttered.start.copy()
    sunk[2] = cluttered.bounds[0][2]
    assert c.is_free(sunk) is False
    assert c.distances(np.stack([sunk]))[0][0] == 0
    # On random configurations, is_free (through the distance grid where it answers) agrees with
    # FCL's exact distance (positive where free).
    rng = np.random.default_rng(5)
    lo, hi = cluttered.bounds
    qs = np.empty((3000, 7))
    qs[:, :3] = rng.uniform(lo, hi, size=(3000, 3))
    quat = rng.normal(size=(3000, 4))
    qs[:, 3:] = quat / np.linalg.norm(quat, axis=1, keepdims=True)
    free = c.is_free(qs)
    assert 0 < free.sum() < len(qs)
    np.testing.assert_array_equal(free, c.distances(qs)[0] > 0)


def test_every_planner_lists_its_parameters_from_the_command_lines_table():
    names = [p["name"] for p in tandem.planners()]
    assert {"birrt", "rrt", "interactive", "interactive-contact", "irrt"} <= set(names)
    rrt = {p["name"]: p for p in tandem.parameters("rrt")}
    assert rrt["goal_bias"]["default"] == 0.05
    assert "alpha" not in rrt
    contact = {p["name"] for p in tandem.parameters("interactive-contact")}
    assert {"alpha", "contact_samples", "contact_distance"} <= contact
    help_text = run_cli("plan", "--help").stdout
    for name in rrt:
        assert "--" + name.replace("_", "-") in help_text, name


def test_errors_are_input_errors_with_tandems_message(cluttered):
    with pytest.raises(tandem.InputError, match="no-such-scene"):
        tandem.Problem("no-such-scene")
    with pytest.raises(tandem.InputError, match="unknown parameter"):
        tandem.plan(cluttered, planner="rrt", no_such=1)
    with pytest.raises(tandem.InputError, match="goal-bias|goal_bias"):
        tandem.plan(cluttered, planner="rrt", goal_bias=7)
    with pytest.raises(tandem.InputError, match="not finite"):
        tandem.Collision(cluttered).is_free([0, 0, float("nan"), 0, 0, 0, 1])
    with pytest.raises(tandem.InputError, match="zero quaternion"):
        tandem.Collision(cluttered).is_free([0, 0, 0, 0, 0, 1e-10, 0])
    with pytest.raises(tandem.InputError, match="shape"):
        tandem.check_path(cluttered, np.zeros((2, 5)))
    with pytest.raises(tandem.InputError, match="unknown planner"):
        tandem.parameters("nope")
    assert issubclass(tandem.InputError, ValueError)


def test_a_quaternion_of_huge_numbers_reads_as_its_direction(cluttered):
    # Squaring 1e200 overflows; the direction (x = z) is still a rotation, and it is not the
    # identity (it read as the zero quaternion, that is as no rotation at all).
    collision = tandem.Collision(cluttered)
    at = [-2.0, 0.0, 0.6]
    turned = collision.nearest(at + [1, 0, 1, 0])
    assert collision.nearest(at + [1e200, 0, 1e200, 0]) == turned
    assert turned != collision.nearest(at + [0, 0, 0, 1])
