"""A Planner is one decision at a time: a decide_many progress callback that calls decide or
decide_many on the same Planner would wait for itself (it blocked for ever, deaf to Ctrl-C), so
it raises RuntimeError, and the Planner is free again afterwards; another Planner may decide
from the callback. The re-entry runs in a child interpreter with a deadline, so a regression
fails the test instead of hanging the test run."""
import foresight
from child_interpreter import MODELS, in_child

SITUATION = MODELS / "situations" / "near_goal_corner.json"


def test_a_progress_callback_calling_its_own_planner_is_refused_not_a_deadlock():
    code, out, err = in_child(f"""
import numpy as np
planner = foresight.Planner({str(SITUATION)!r})
calls = []
def progress(label, done, total):
    calls.append(done)
    planner.decide()
try:
    planner.decide_many(np.zeros((3, 3)), progress=progress)
except RuntimeError as e:
    print(str(e))
print(planner.decide().kick_index >= -1)
""", timeout=60)  # before the refusal: blocked for ever (TimeoutExpired)
    assert code == 0, err
    lines = out.strip().splitlines()
    assert lines[0].startswith("Planner: decide and decide_many cannot be called from within a "
                               "decide_many of the same planner")
    assert lines[1] == "True"  # the planner is free again


def test_a_progress_callback_may_use_another_planner():
    other = foresight.Planner(SITUATION)
    seen = []
    planner = foresight.Planner(SITUATION)
    import numpy as np
    planner.decide_many(np.zeros((2, 3)),
                        progress=lambda *_: seen.append(other.decide().kick_index))
    assert seen
