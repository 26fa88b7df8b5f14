"""The Python module's errors and Ctrl-C: InputError cut as the command line cuts it, and
SIGINT during a long call raising KeyboardInterrupt instead of waiting for the call's end."""
import os
import pathlib
import signal
import threading

import pytest

import foresight

MODELS = pathlib.Path(os.environ["FORESIGHT_SOURCE_DIR"]) / "models"


def test_input_error_is_one_line_cut_as_the_command_line_cuts_it():
    with pytest.raises(foresight.InputError) as raised:
        foresight.decide(situation="x" * 100000 + "\n.json")
    message = str(raised.value)
    assert len(message) < 2100
    assert message.endswith(" bytes)")
    assert "\n" not in message


def test_ctrl_c_ends_a_long_simulate_with_keyboard_interrupt():
    # A million trials run for hours: the call ends only because the interrupt ends it (the
    # test's deadline is ctest's timeout, no timing assumption).
    timer = threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            foresight.simulate(str(MODELS / "situations" / "open_goal.json"), "forward",
                               trials=1000000, threads=2)
    finally:
        timer.cancel()
    # The next call is not interrupted by the Ctrl-C that ended this one.
    out = foresight.simulate(str(MODELS / "situations" / "open_goal.json"), "forward", trials=4,
                             threads=1)
    assert len(out["rest_x_m"]) == 4
