"""The Python module `foresight` as a researcher uses it: the same answers as the
command line, arrays of the documented shape and units, bad input as foresight.InputError with
the command's one-line message, and the worked example run end to end (Agg backend)."""
import json
import math
import os
import pathlib
import runpy
import subprocess

import numpy as np
import pytest

import foresight

BINARY = os.environ["FORESIGHT_BINARY"]
SOURCE = pathlib.Path(os.environ["FORESIGHT_SOURCE_DIR"])
MODELS = SOURCE / "models"
SITUATION = str(MODELS / "situations" / "near_goal_corner.json")


def cli(*args):
    """Runs the foresight command; returns (exit code, stdout, stderr)."""
    done = subprocess.run([BINARY, *args], capture_output=True, text=True, check=False)
    return done.returncode, done.stdout, done.stderr


def cli_error(*args):
    """The one-line message the command prints for bad input, without its prefix."""
    code, _, err = cli(*args)
    assert code == 2
    assert err.startswith("foresight: error: ") and err.count("\n") == 1
    return err[len("foresight: error: "):].rstrip("\n")


@pytest.mark.parametrize("strategy,seed", [("optimal_all", 1), ("fast", 7), ("naoth", 3)])
def test_decide_equals_the_cli_json(strategy, seed):
    code, out, _ = cli("decide", "--situation", SITUATION, "--strategy", strategy,
                       "--seed", str(seed), "--json")
    assert code == 0
    assert foresight.decide(SITUATION, strategy=strategy, seed=seed) == json.loads(out)


def test_decide_with_samples_and_kicks_equals_the_cli_json():
    kicks = str(MODELS / "kicks" / "nao_calibrated.json")
    code, out, _ = cli("decide", "--situation", SITUATION, "--samples", "12", "--kicks", kicks,
                       "--json")
    assert code == 0
    assert foresight.decide(SITUATION, samples=12, kicks=kicks) == json.loads(out)


@pytest.mark.parametrize("problem", ["open_pass", "blocked_pass", "nothing_retrieved"])
def test_cbr_retrieve_equals_the_cli_json(problem):
    path = str(MODELS / "cbr" / "problems" / f"{problem}.json")
    code, out, _ = cli("cbr", "retrieve", "--problem", path, "--json")
    assert code == 0
    assert foresight.cbr_retrieve(path) == json.loads(out)


def test_cbr_retrieve_bad_problem_raises_the_cli_message(tmp_path):
    bad = tmp_path / "problem.json"
    bad.write_text('{"defending": "cyan", "ball": {"x_m": 9.0, "y_m": 0.0}, '
                   '"teammates": [{"id": 1, "x_m": 0.0, "y_m": 0.0, "theta_deg": 0}]}')
    with pytest.raises(foresight.InputError) as raised:
        foresight.cbr_retrieve(str(bad))
    assert str(raised.value) == cli_error("cbr", "retrieve", "--problem", str(bad))


def test_simulate_arrays_have_one_entry_per_trial_and_match_the_cli():
    trials = foresight.simulate(SITUATION, "forward", trials=6, seed=4)
    for name in ("rest_x_m", "rest_y_m", "time_s", "launch_speed_mps", "launch_direction_deg",
                 "placement_dx_m", "placement_dy_m", "placement_dtheta_deg", "speed_factor",
                 "carpet_factor"):
        assert trials[name].shape == (6,) and trials[name].dtype == np.float64, name
    for name in ("category", "first_contact", "status"):
        assert trials[name].dtype == np.int8
    assert trials["touched"].dtype == np.bool_
    assert trials["placement_redraws"].dtype == np.int32  # placements that put the ball inside
    assert trials["category_names"] == ["infield", "opp_goal", "own_goal", "out"]
    assert trials["contact_names"] == ["none", "post", "net", "obstacle", "robot"]
    assert trials["status_names"] == ["ok", "missed", "not_settled", "fell", "blocked"]
    # The same trials as `foresight simulate --json`, in metres and degrees.
    code, out, _ = cli("simulate", "--situation", SITUATION, "--kick", "forward", "--trials", "6",
                       "--seed", "4", "--json")
    assert code == 0
    report = json.loads(out)
    assert len(report["trials_detail"]) == 6
    for i, trial in enumerate(report["trials_detail"]):
        assert [trials["rest_x_m"][i], trials["rest_y_m"][i]] == trial["rest_m"]
        assert trials["category_names"][trials["category"][i]] == trial["category"]
        assert trials["contact_names"][trials["first_contact"][i]] == trial["first_contact"]
        assert trials["time_s"][i] == trial["time_s"]
        assert trials["touched"][i] == trial["touched"]
        assert trials["launch_speed_mps"][i] == trial["launch_speed_mps"]
        assert trials["launch_direction_deg"][i] == pytest.approx(trial["launch_direction_deg"],
                                                                  abs=1e-12)
        assert trials["speed_factor"][i] == trial["draw"]["motion_speed_factor"]
        assert trials["carpet_factor"][i] == trial["draw"]["carpet_factor"]
        assert trials["placement_dx_m"][i] == trial["draw"]["placement_dx_m"]
        assert trials["placement_redraws"][i] == trial["draw"]["placement_redraws"]
    # Launch speeds of a NAO forward kick: a few tenths of a metre per second to a few m/s.
    speeds = trials["launch_speed_mps"][trials["touched"]]
    assert speeds.size > 0 and np.all((speeds > 0.1) & (speeds < 10.0))


def test_simulate_does_not_depend_on_threads():
    one = foresight.simulate(SITUATION, "forward", trials=4, seed=2, threads=1)
    two = foresight.simulate(SITUATION, "forward", trials=4, seed=2, threads=2)
    for name, values in one.items():
        if isinstance(values, np.ndarray):
            assert np.array_equal(values, two[name]), name


def test_fidelity_equals_the_cli_report(tmp_path):
    # On the fixed base, the cheap approximation: the quick set's 648 trials twice, for the
    # module's and the command's equality, which does not depend on the base.
    args = ["--situations", "quick", "--trials", "3", "--converged", "100", "--seed", "5",
            "--base", "fixed"]
    code, _, _ = cli("fidelity", *args, "--out", str(tmp_path / "f"))
    assert code == 0
    report = json.loads((tmp_path / "f" / "fidelity.json").read_text())
    mine = foresight.fidelity(situations="quick", trials=3, converged=100, seed=5, base="fixed")
    for run in (report, mine):
        run.pop("run_time_s")  # the one field two runs with the same seed may differ in
    assert mine == report


def test_calibrate_equals_the_cli_report(tmp_path):
    code, _, _ = cli("calibrate", "--robot", "nao", "--kick", "forward", "--trials", "24",
                     "--resamples", "200", "--out", str(tmp_path / "k.json"),
                     "--report", str(tmp_path / "r"))
    assert code == 0
    report = json.loads((tmp_path / "r" / "calibration.json").read_text())
    mine = foresight.calibrate("nao", kick="forward", trials=24, resamples=200)
    assert report["files"].pop("out") == str(tmp_path / "k.json")
    assert mine["files"].pop("out") == ""  # the module writes no kick-model file
    for run in (report, mine):
        run.pop("run_time_s")
    assert mine == report
    assert mine["kicks"][0]["observations"] == 24


def test_loaders_return_the_checked_files():
    situation = foresight.load_situation(SITUATION)
    assert situation["name"] == "near_goal_corner"
    assert situation["kicks"] == ["forward", "side_kick_left", "side_kick_right"]
    assert situation["robot"]["theta_rad"] == pytest.approx(math.radians(10))
    kicks = foresight.load_kick_model(str(MODELS / "kicks" / "nao.json"))
    assert kicks == json.loads((MODELS / "kicks" / "nao.json").read_text())
    field = foresight.load_field(str(MODELS / "fields" / "spl.json"))
    assert field == json.loads((MODELS / "fields" / "spl.json").read_text())


@pytest.mark.parametrize("call,args", [
    (lambda: foresight.decide(SITUATION, strategy="best"),
     ["decide", "--situation", SITUATION, "--strategy", "best"]),
    (lambda: foresight.decide(SITUATION, samples=0),
     ["decide", "--situation", SITUATION, "--samples", "0"]),
    (lambda: foresight.decide("/nonexistent/situation.json"),
     ["decide", "--situation", "/nonexistent/situation.json"]),
    (lambda: foresight.simulate(SITUATION, "bicycle_kick", trials=2),
     ["simulate", "--situation", SITUATION, "--kick", "bicycle_kick", "--trials", "2"]),
    (lambda: foresight.simulate(SITUATION, "forward", trials=0),
     ["simulate", "--situation", SITUATION, "--kick", "forward", "--trials", "0"]),
    (lambda: foresight.fidelity(situations="nonexistent"),
     ["fidelity", "--situations", "nonexistent", "--out", "/tmp/foresight-never-written"]),
    (lambda: foresight.calibrate("nao", kick="forward", trials=3),
     ["calibrate", "--robot", "nao", "--kick", "forward", "--trials", "3", "--out",
      "/tmp/foresight-never-written.json"]),
])
def test_bad_input_raises_the_commands_one_line_message(call, args):
    with pytest.raises(foresight.InputError) as raised:
        call()
    assert str(raised.value) == cli_error(*args)
    assert isinstance(raised.value, ValueError)


def test_loaders_raise_on_bad_files(tmp_path):
    bad = tmp_path / "kicks.json"
    bad.write_text('{"robot": "nao", "kicks": [}')
    with pytest.raises(foresight.InputError, match="kicks.json: invalid JSON at line 1"):
        foresight.load_kick_model(str(bad))


def test_worked_example_runs_with_the_agg_backend(tmp_path):
    out = tmp_path / "launch_speeds.png"
    example = runpy.run_path(str(SOURCE / "python" / "examples" / "calibrate_and_plot.py"))
    report = example["main"](str(out), 24)
    assert out.stat().st_size > 10000  # a real figure
    assert [k["name"] for k in report["kicks"]] == ["forward", "side_kick_left", "side_kick_right"]
    for kick in report["kicks"]:
        assert 0.0 < kick["speed"]["sd_mps"] < kick["speed"]["mean_mps"]
