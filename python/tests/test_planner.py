"""The module's in-memory objects: a Planner built once from a file or from Python data decides
as the command line does (the same bytes of JSON for the same seed), for any pose given as a
Pose, a dict or a tuple, and row by row for NumPy arrays; KickModel, CaseBase and passing()
(trial by trial with `experiment passing`'s CSV) agree with the command line too; bad input names the argument, the field and the value."""
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import foresight

BINARY = os.environ["FORESIGHT_BINARY"]
SOURCE = pathlib.Path(os.environ["FORESIGHT_SOURCE_DIR"])
MODELS = SOURCE / "models"
SITUATION = MODELS / "situations" / "near_goal_corner.json"


def cli_json(*args):
    done = subprocess.run([BINARY, *args, "--json"], capture_output=True, text=True, check=True)
    return json.loads(done.stdout)


def without_file(decision):
    """A decision's JSON without the situation's file, which only a file has."""
    decision["situation"].pop("file")
    return decision


def situation_dict(path=SITUATION):
    """The situation file's content as a dict (notes left out: a dict needs none)."""
    content = json.loads(pathlib.Path(path).read_text())
    content.pop("notes", None)
    return content


@pytest.mark.parametrize("strategy", ["optimal_all", "fast", "naoth", "optimal_value"])
def test_a_planner_decides_as_the_command_line(strategy):
    planner = foresight.Planner(SITUATION, strategy=strategy)
    for seed in (1, 5, 9):
        cli = cli_json("decide", "--situation", str(SITUATION), "--strategy", strategy,
                       "--seed", str(seed))
        decision = planner.decide(seed=seed)
        assert decision.to_dict() == cli
        assert decision.kick == cli["decision"]["kick"]
        assert decision.rotation_deg == cli["decision"]["rotation_deg"]
        assert decision.hypotheses == cli["hypotheses_simulated"]


def test_paths_and_dicts_decide_alike():
    by_path = foresight.decide(SITUATION, seed=3)  # a pathlib.Path
    by_dict = foresight.decide(situation_dict(), seed=3)
    assert by_dict["situation"].pop("file") == ""
    assert by_path["situation"].pop("file") == str(SITUATION)
    assert by_dict == by_path


def test_a_pose_as_object_dict_or_tuple_is_the_same_pose():
    planner = foresight.Planner(SITUATION)
    pose = foresight.Pose(2.0, -1.0, 30.0)
    ball = foresight.Ball(0.2, 0.05)
    expected = planner.decide(robot=pose, ball=ball, seed=4).to_dict()
    assert planner.decide(robot=(2.0, -1.0, 30.0), ball=(0.2, 0.05), seed=4).to_dict() == expected
    assert planner.decide(robot={"x_m": 2.0, "y_m": -1.0, "theta_deg": 30.0},
                          ball={"x_m": 0.2, "y_m": 0.05}, seed=4).to_dict() == expected
    # ... and the same as a situation written with that pose and the file's sigmas.
    content = situation_dict()
    content["robot"].update(x_m=2.0, y_m=-1.0, theta_deg=30.0)
    content["ball"].update(x_m=0.2, y_m=0.05)
    assert without_file(foresight.Planner(content).decide(seed=4).to_dict()) == \
        without_file(expected)


def test_sigmas_given_with_a_pose_replace_the_situations():
    planner = foresight.Planner(SITUATION)
    sharp = planner.decide(robot=foresight.Pose(3.6, 1.9, 10.0, 0.0, 0.0, 0.0),
                           ball=foresight.Ball(0.15, 0.0, 0.0, 0.0), seed=2)
    content = situation_dict()
    for key in ("sigma_x_m", "sigma_y_m", "sigma_theta_deg"):
        content["robot"][key] = 0.0
    for key in ("sigma_x_m", "sigma_y_m"):
        content["ball"][key] = 0.0
    assert without_file(foresight.Planner(content).decide(seed=2).to_dict()) == \
        without_file(sharp.to_dict())


def test_obstacles_and_kick_models_from_python_objects():
    kicks = foresight.KickModel(MODELS / "kicks" / "nao_calibrated.json")
    assert kicks.names == ["forward", "side_kick_left", "side_kick_right", "forward_long"]
    assert foresight.KickModel(kicks.to_dict()).to_dict() == kicks.to_dict()
    content = situation_dict()
    content["obstacles"] = [foresight.Obstacle(4.2, 1.2, 0.2)]
    with_object = foresight.Planner(content, kicks=kicks).decide(seed=6).to_dict()
    content["obstacles"] = [{"x_m": 4.2, "y_m": 1.2, "radius_m": 0.2}]
    with_dict = foresight.Planner(content, kicks=kicks.to_dict()).decide(seed=6).to_dict()
    assert with_object["decision"] == with_dict["decision"]
    assert with_object["kicks"] == with_dict["kicks"]
    # The obstacle is in the scene: it changes what the kicks score.
    plain = foresight.Planner(situation_dict(), kicks=kicks).decide(seed=6).to_dict()
    assert plain["kicks"] != with_dict["kicks"]


def test_decide_many_equals_decide_row_by_row():
    planner = foresight.Planner(SITUATION, samples=20)
    rng = np.random.default_rng(5)
    robots = np.column_stack([rng.uniform(-4, 4, 40), rng.uniform(-2.8, 2.8, 40),
                              rng.uniform(-180, 180, 40)])
    balls = np.column_stack([rng.uniform(0.1, 0.3, 40), rng.uniform(-0.1, 0.1, 40)])
    seeds = np.arange(40, dtype=np.uint64) * 7
    many = planner.decide_many(robots, balls, seed=seeds)
    assert many["kick_index"].dtype == np.int32 and many["kick_index"].shape == (40,)
    assert many["kick_names"] == planner.kick_names
    for i in range(40):
        d = planner.decide(robot=tuple(robots[i]), ball=tuple(balls[i]), seed=int(seeds[i]))
        assert many["kick_index"][i] == d.kick_index
        assert many["rotation_deg"][i] == d.rotation_deg
        assert many["hypotheses"][i] == d.hypotheses
        chosen = d.to_dict()
        entry = chosen["none"] if d.kick_index < 0 else chosen["kicks"][d.kick_index]
        assert many["trimmed_utility"][i] == entry["trimmed_utility"]
    # One seed for every row.
    same = planner.decide_many(robots[:3], seed=11)
    for i in range(3):
        assert same["kick_index"][i] == planner.decide(robot=tuple(robots[i]), seed=11).kick_index


def test_bad_input_names_the_argument_and_the_value():
    planner = foresight.Planner(SITUATION)
    with pytest.raises(foresight.InputError, match=r"^robot: position \(9, 0\) is outside"):
        planner.decide(robot=(9.0, 0.0, 0.0))
    with pytest.raises(foresight.InputError, match=r"^robot: must be \(x_m, y_m, theta_deg\)"):
        planner.decide(robot=(1.0, 2.0))
    with pytest.raises(foresight.InputError, match=r"^robot\.theta_deg: must be a number"):
        planner.decide(robot={"x_m": 1.0, "y_m": 0.0, "theta_deg": "north"})
    with pytest.raises(foresight.InputError, match=r"^strategy: unknown strategy 'best'"):
        planner.decide(strategy="best")
    with pytest.raises(foresight.InputError, match=r"^seed: must be an integer"):
        planner.decide(seed=-1)
    with pytest.raises(foresight.InputError, match=r"^robots\[1\]: robot: position"):
        planner.decide_many(np.array([[0.0, 0.0, 0.0], [0.0, 7.0, 0.0]]))
    with pytest.raises(foresight.InputError, match=r"^robots: must be an array of shape \(N, 3\)"):
        planner.decide_many(np.zeros((4, 2)))
    content = situation_dict()
    content["robot"]["x_m"] = "far"
    with pytest.raises(foresight.InputError,
                       match=r"^situation \(dict\): robot\.x_m: must be a number"):
        foresight.Planner(content)
    with pytest.raises(foresight.InputError, match=r"^situation: must be a path or a dict"):
        foresight.Planner(42)


def test_the_case_base_retrieves_for_files_and_dicts():
    base = foresight.CaseBase()
    assert base.size > 0
    for name in ("open_pass", "blocked_pass", "nothing_retrieved"):
        path = MODELS / "cbr" / "problems" / f"{name}.json"
        cli = cli_json("cbr", "retrieve", "--problem", str(path))
        assert base.retrieve(path) == cli
        content = json.loads(path.read_text())
        content.pop("notes", None)
        mine = base.retrieve(content)
        assert mine["problem"].pop("file") == ""  # a dict is no file; the rest is the same
        assert cli["problem"].pop("file") == str(path)
        assert mine == cli
        assert foresight.cbr_retrieve(content) == base.retrieve(content)


def test_passing_plays_the_match_simulator_deterministically():
    one = foresight.passing("dg", scenarios=[1, 2], trials=3, seed=4, threads=1)
    two = foresight.passing("dg", scenarios=[1, 2], trials=3, seed=4, threads=2)
    assert one["team_names"] == ["reactive"]
    assert list(one["scenario"]) == [1, 1, 1, 2, 2, 2]
    assert list(one["trial"]) == [0, 1, 2, 0, 1, 2]
    assert one["outcome_names"] == ["goal", "close", "block", "out", "penalty_area", "timeout"]
    for name, values in one.items():
        if isinstance(values, np.ndarray):
            assert np.array_equal(values, two[name]), name
    assert np.all(one["time_s"] > 0)
    with pytest.raises(foresight.InputError):
        foresight.passing("dg", trials=0)


def test_passing_plays_the_trials_of_the_command(tmp_path):
    out = tmp_path / "passing"
    subprocess.run([BINARY, "experiment", "passing", "--config", "dg", "--team", "cbr",
                    "--scenarios", "1,2", "--trials", "4", "--seed", "2", "--out", str(out)],
                   capture_output=True, check=True)
    lines = (out / "passing_trials.csv").read_text().splitlines()
    rows = [dict(zip(lines[0].split(","), line.split(","))) for line in lines[1:]]
    mine = foresight.passing("dg", team="cbr", scenarios=[1, 2], trials=4, seed=2)
    assert mine["team_names"] == ["cbr"] and len(rows) == 8
    for i, row in enumerate(rows):
        assert int(row["scenario"]) == mine["scenario"][i]
        assert int(row["trial"]) == mine["trial"][i]
        assert row["outcome"] == mine["outcome_names"][mine["outcome"][i]]
        assert float(row["time_s"]) == pytest.approx(mine["time_s"][i], abs=0.005)
        assert int(row["kicks_A"]) + int(row["kicks_B"]) == mine["attacker_kicks"][i]
        assert int(row["touches_D"]) + int(row["touches_G"]) == mine["opponent_touches"][i]
        assert int(row["shots_on_target"]) == mine["shots_on_target"][i]
        assert int(row["grabs_failed"]) == mine["grabs_failed"][i]


def test_passing_with_physics_takes_the_base_and_plays_the_command_trials(tmp_path):
    # The fixed base, the cheap approximation: what is tested is that base= reaches the
    # physics executor as --base does, and that the kicks' statuses come back per trial.
    out = tmp_path / "passing"
    subprocess.run([BINARY, "experiment", "passing", "--config", "dg", "--scenarios", "4",
                    "--trials", "2", "--seed", "3", "--physics", "--base", "fixed",
                    "--out", str(out)], capture_output=True, check=True)
    lines = (out / "passing_trials.csv").read_text().splitlines()
    rows = [dict(zip(lines[0].split(","), line.split(","))) for line in lines[1:]]
    assert json.loads((out / "passing.json").read_text())["params"]["robot_base"] == "fixed"
    mine = foresight.passing("dg", scenarios=[4], trials=2, seed=3, physics=True, base="fixed")
    assert len(rows) == 2
    for i, row in enumerate(rows):
        assert row["outcome"] == mine["outcome_names"][mine["outcome"][i]]
        assert float(row["time_s"]) == pytest.approx(mine["time_s"][i], abs=0.005)
        for status in ("kicks_missed", "kicks_not_settled", "kicks_fell", "kicks_blocked"):
            assert mine[status].dtype == np.int32
            assert int(row[status]) == mine[status][i], status
    with pytest.raises(foresight.InputError, match="--base needs --physics"):
        foresight.passing("dg", trials=1, base="fixed")
    with pytest.raises(foresight.InputError, match="--base: must be one of"):
        foresight.passing("dg", trials=1, physics=True, base="bolted")
