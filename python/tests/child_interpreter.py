"""Running test code in a new interpreter, so a crash or a hang fails one test instead of ending
the whole test run. MODELS is the source tree's models folder; the child has it too."""
import os
import pathlib
import subprocess
import sys
import textwrap

MODELS = pathlib.Path(os.environ["FORESIGHT_SOURCE_DIR"]) / "models"


def in_child(code, timeout=120):
    """Runs `code` in a new interpreter; returns (exit code, stdout, stderr)."""
    prelude = f"import foresight, json, pathlib\nMODELS = pathlib.Path({str(MODELS)!r})\n"
    done = subprocess.run([sys.executable, "-c", prelude + textwrap.dedent(code)],
                          capture_output=True, text=True, timeout=timeout, check=False)
    return done.returncode, done.stdout, done.stderr
