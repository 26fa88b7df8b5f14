"""Keyword arguments as the command line's flags: '' is refused, never taken for "not given"
(None is), a bool argument takes only True, False or None, an integer beyond 64 bits is an
InputError naming the argument, and decide_many refuses complex and masked arrays instead of
casting away their imaginary part or mask."""
import os
import pathlib

import pytest

import foresight

MODELS = pathlib.Path(os.environ["FORESIGHT_SOURCE_DIR"]) / "models"
SITUATION = MODELS / "situations" / "near_goal_corner.json"
PROBLEM = MODELS / "cbr" / "problems" / "open_pass.json"


@pytest.mark.parametrize("call,argument", [
    (lambda: foresight.decide(str(SITUATION), samples=""), "samples"),
    (lambda: foresight.decide(str(SITUATION), kicks=""), "kicks"),
    (lambda: foresight.load_situation(str(SITUATION), kicks=""), "kicks"),
    (lambda: foresight.CaseBase(case_base=""), "case_base"),
    (lambda: foresight.cbr_retrieve(str(PROBLEM), params=""), "params"),
    (lambda: foresight.simulate(str(SITUATION), "forward", physics=""), "physics"),
    (lambda: foresight.simulate(str(SITUATION), "forward", base=""), "base"),
    (lambda: foresight.calibrate("nao", kick=""), "kick"),
    (lambda: foresight.calibrate("nao", from_csv=""), "from_csv"),
    (lambda: foresight.calibrate("nao", physics=""), "physics"),
    (lambda: foresight.fidelity(samples=""), "samples"),
    (lambda: foresight.fidelity(models=""), "models"),
    (lambda: foresight.simulate(str(SITUATION), "forward", models=""), "models"),
    (lambda: foresight.models_dir(models=""), "models"),
])
def test_an_empty_argument_is_refused_not_taken_for_none(call, argument):
    with pytest.raises(foresight.InputError,
                       match=rf"^{argument}: empty value \(pass None for the default\)$"):
        call()


@pytest.mark.parametrize("value", [float("nan"), 1.5, -1, 0, 1, "on"])
def test_coarse_rebounds_takes_only_a_bool(value):
    with pytest.raises(foresight.InputError,
                       match=r"^coarse_rebounds: must be True, False or None"):
        foresight.Planner(SITUATION, coarse_rebounds=value)


def test_coarse_rebounds_as_a_string_is_an_input_error():
    with pytest.raises(foresight.InputError,
                       match=r"^coarse_rebounds: must be True, False or None, got 'yes'$"):
        foresight.Planner(SITUATION, coarse_rebounds="yes")


def test_coarse_rebounds_true_and_false_still_work():
    assert foresight.Planner(SITUATION, coarse_rebounds=True).decide().kick_index >= -1
    assert foresight.Planner(SITUATION, coarse_rebounds=False).decide().kick_index >= -1


def test_samples_beyond_64_bits_is_an_input_error():
    big = str(2 ** 70)
    with pytest.raises(foresight.InputError,
                       match=rf"^samples: must be an integer in \[1, \d+\], got {big}$"):
        foresight.Planner(SITUATION, samples=2 ** 70)


def test_complex_and_masked_rows_are_refused_not_cast():
    import numpy as np
    planner = foresight.Planner(SITUATION)
    with pytest.raises(foresight.InputError, match=r"^robots: complex numbers"):
        planner.decide_many(np.zeros((2, 3)) + 1j)
    masked = np.ma.masked_array(np.zeros((2, 3)), mask=[[0, 0, 0], [1, 0, 0]])
    with pytest.raises(foresight.InputError, match=r"^robots: a masked array"):
        planner.decide_many(masked)
    with pytest.raises(foresight.InputError, match=r"^balls: complex numbers"):
        planner.decide_many(np.zeros((2, 3)), balls=np.zeros((2, 2), dtype=complex))
