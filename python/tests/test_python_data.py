"""Python data given in place of a file (a dict, as the file's content) is converted to JSON
with the JSON reader's limits checked before each step down: a dict or list that holds itself
or nests deeper than 64 levels is one InputError naming the argument and the place, never a
C++ stack overflow (SIGSEGV), and an integer beyond 64 bits names its field. The crashes ran in
a child interpreter, so a regression fails the test instead of ending the test run."""
import json
import pathlib

import pytest

import foresight
from child_interpreter import MODELS, in_child

SITUATION = MODELS / "situations" / "near_goal_corner.json"


def content(path):
    data = json.loads(pathlib.Path(path).read_text())
    data.pop("notes", None)
    return data


@pytest.mark.parametrize("call", [
    "foresight.Planner(d)", "foresight.decide(d)", "foresight.KickModel(d)",
    "foresight.cbr_retrieve(d)"])
@pytest.mark.parametrize("shape", ["dict_in_itself", "list_in_itself", "deep_dict"])
def test_self_holding_and_deep_data_is_one_input_error(call, shape):
    make = {
        "dict_in_itself": "d = {}\nd['self'] = d\n",
        "list_in_itself": "d = {'list': []}\nd['list'].append(d['list'])\n",
        "deep_dict": "d = {}\nx = d\nfor _ in range(100000):\n    x['a'] = {}\n    x = x['a']\n",
    }[shape]
    code, out, err = in_child(make + f"""
try:
    {call}
except foresight.InputError as e:
    print(str(e))
""")
    assert code == 0, err  # before the limits: SIGSEGV (-11)
    argument = {"KickModel": "kicks", "cbr_retrieve": "problem"}.get(
        call.split("(")[0].split(".")[1], "situation")
    expected = {
        "dict_in_itself": f"{argument}: self: holds itself (a dict or list inside itself)",
        "list_in_itself": f"{argument}: list[0]: holds itself (a dict or list inside itself)",
        "deep_dict": f"{argument}: " + ".".join(["a"] * 64) + ": nested deeper than 64 levels",
    }[shape]
    assert out.strip() == expected


def test_data_at_the_depth_limit_still_reads_as_the_file_reader_would():
    # 64 levels are the JSON reader's limit too: the file reader, not the conversion, refuses
    # the unknown key, so the conversion let all 64 through.
    data = content(SITUATION)
    deep = {}
    inner = deep
    for _ in range(62):
        inner["a"] = {}
        inner = inner["a"]
    data["extra"] = deep
    with pytest.raises(foresight.InputError, match=r"^situation \(dict\): extra"):
        foresight.Planner(data)


def test_a_value_in_two_places_is_data_not_a_cycle():
    # The same dict under two keys holds nothing of itself: the conversion passes it and the
    # file reader refuses the keys it does not know, the first of them.
    shared = {"x_m": 1.0}
    data = content(SITUATION)
    data["extra"] = [shared, shared]
    with pytest.raises(foresight.InputError, match=r"^situation \(dict\): .*extra"):
        foresight.Planner(data)


def test_integers_beyond_64_bits_name_the_argument_and_the_field():
    data = content(SITUATION)
    data["robot"]["x_m"] = 2 ** 70
    big = str(2 ** 70)
    with pytest.raises(foresight.InputError,
                       match=rf"^situation: robot\.x_m: an integer beyond 64 bits: {big}$"):
        foresight.Planner(data)
