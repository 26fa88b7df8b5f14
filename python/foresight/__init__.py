"""foresight: robot-soccer kick selection by forward simulation (Mellmann & Schlotter 2017),
checked against Bullet physics, and case-based coordinated action selection (Ros et al. 2009).

Objects built once and reused:
    Planner(situation, kicks=None, strategy=None, samples=None, coarse_rebounds=None, models=None)
        .decide(robot=None, ball=None, seed=1, strategy=None, samples=None) -> Decision
        .decide_many(robots, balls=None, seed=1, ...) -> dict of NumPy arrays
    Pose(x_m, y_m, theta_deg), Ball(x_m, y_m), Obstacle(x_m, y_m, radius_m), KickModel(source)
    CaseBase(case_base=None, params=None).retrieve(problem) -> dict

Functions that do what the command of the same name does and return what it writes as JSON:
    decide, simulate (NumPy arrays per trial), calibrate, fidelity, passing (NumPy arrays per
    match trial), cbr_retrieve, load_situation, load_kick_model, load_field, models_dir.

Inputs: a situation, kick model or CBR problem is a path (str or os.PathLike) or a dict with the
file's keys; both are checked by the same reader. Bad input raises InputError (a ValueError)
with a one-line message naming the file or argument, the field and the value.

Strategies: fast, optimal_value, optimal_all (the default), optimal_one, naoth.

Units and frames: metres, seconds, m/s and degrees in every name that carries them (x_m,
theta_deg, speed_mps); F is the field frame (origin at the centre, x towards the opponent goal),
R the robot frame (x ahead, y to the left); a robot pose is in F, the ball of a situation in R.

Long calls (simulate, calibrate, fidelity, passing, Planner.decide_many) run without the GIL,
stop with KeyboardInterrupt on Ctrl-C within a fraction of a second, and take
progress=callable(label, done, total).
"""
from . import _foresight
from ._foresight import *  # noqa: F401,F403  (the native module's public names)
from ._foresight import __version__  # noqa: F401

# The native module's classes and its exception belong to this package in reprs and tracebacks.
for _name in dir(_foresight):
    _value = getattr(_foresight, _name)
    if isinstance(_value, type) and getattr(_value, "__module__", "").endswith("_foresight"):
        try:
            _value.__module__ = __name__
        except (AttributeError, TypeError):
            pass
del _name, _value
