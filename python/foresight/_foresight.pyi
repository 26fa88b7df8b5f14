"""Typed stubs of the native module foresight._foresight (python/*.cc); `import foresight` gives
all of these names. Units and frames are in the names: metres (_m), seconds (_s), m/s (_mps),
degrees (_deg); F is the field frame, R the robot frame."""
import os
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

PathLike = Union[str, "os.PathLike[str]"]
Json = Dict[str, Any]
# progress(label, done, total): e.g. ("calibrate forward", 300, 1000); from any thread.
Progress = Optional[Callable[[str, int, int], object]]
# The strategies: "fast", "optimal_value", "optimal_all", "optimal_one", "naoth".
Strategy = str

class InputError(ValueError):
    """Bad input: the one-line message names the file or argument, the field and the value."""

class Pose:
    """A robot pose in F: x_m, y_m (metres), theta_deg (degrees, 0 = towards the opponent goal,
    counter-clockwise); sigma_* the belief's standard deviations (None: the situation's)."""
    x_m: float
    y_m: float
    theta_deg: float
    sigma_x_m: Optional[float]
    sigma_y_m: Optional[float]
    sigma_theta_deg: Optional[float]
    def __init__(self, x_m: float, y_m: float, theta_deg: float,
                 sigma_x_m: Optional[float] = None, sigma_y_m: Optional[float] = None,
                 sigma_theta_deg: Optional[float] = None) -> None: ...
    def to_dict(self) -> Dict[str, float]:
        """The situation file's "robot" object (unset sigmas left out)."""

class Ball:
    """The ball relative to the robot in R: x_m ahead, y_m to the left (metres); sigma_* the
    belief's standard deviations (None: the situation's)."""
    x_m: float
    y_m: float
    sigma_x_m: Optional[float]
    sigma_y_m: Optional[float]
    def __init__(self, x_m: float, y_m: float, sigma_x_m: Optional[float] = None,
                 sigma_y_m: Optional[float] = None) -> None: ...
    def to_dict(self) -> Dict[str, float]:
        """The situation file's "ball" object (unset sigmas left out)."""

class Obstacle:
    """An obstacle robot in F: a disc at x_m, y_m of radius_m (None: the field's default)."""
    x_m: float
    y_m: float
    radius_m: Optional[float]
    def __init__(self, x_m: float, y_m: float, radius_m: Optional[float] = None) -> None: ...
    def to_dict(self) -> Dict[str, float]:
        """One item of the situation file's "obstacles"."""

class KickModel:
    """A checked kick model from a path or a dict with the file's keys: robot,
    rolling_deceleration_mps2, kicks [{name, speed_mps, sigma_speed_mps, direction_deg,
    sigma_direction_deg, launch_offset_m}]."""
    robot: str
    source: str
    rolling_deceleration_mps2: float
    names: List[str]
    def __init__(self, source: Union[PathLike, Mapping[str, Any]]) -> None: ...
    def to_dict(self) -> Json:
        """The model as its file's content."""

class Decision:
    """One decision of a Planner."""
    kick: str  # the chosen kick's name, or "none" (leave the ball)
    kick_index: int  # into Planner.kick_names; -1 for none
    rotation_deg: float  # the turn around the ball before the kick, counter-clockwise
    note: str  # why a fallback was taken; empty normally
    strategy: Strategy
    hypotheses: int  # (kick, rotation) hypotheses simulated
    samples: int  # samples per hypothesis
    seed: int
    def to_dict(self) -> Json:
        """What `foresight decide --json` prints: situation files, strategy, samples, seed,
        decision {kick, rotation_deg, note}, kicks [{name, considered, no_acceptable_rotation,
        chosen, rotation_deg, p_opp_goal, p_own_goal, p_out, p_infield, value_avg,
        potential_avg, utility, trimmed_utility, too_risky}], none {...},
        hypotheses_simulated."""

RobotArg = Union[Pose, Mapping[str, float], Sequence[float], None]
BallArg = Union[Ball, Mapping[str, float], Sequence[float], None]

class Planner:
    """The coarse decision for one scene, built once and reused.

    situation: a situation file (path) or a dict with its keys: field (name or path), kicks
    (name or path), evaluation (optional), robot {x_m, y_m, theta_deg, sigma_x_m, sigma_y_m,
    sigma_theta_deg} in F, ball {x_m, y_m, sigma_x_m, sigma_y_m} in R, obstacles [{x_m, y_m,
    radius_m}] in F (Pose, Ball and Obstacle objects are accepted as values). kicks: a kick
    model (path, dict or KickModel) replacing the situation's. strategy: the default strategy
    (optimal_all); samples: per hypothesis (None: the evaluation file's N).
    """
    situation: Json  # name, files, kick names, belief (robot in F, ball in R), obstacles
    kick_names: List[str]
    strategy: Strategy
    samples: int
    def __init__(self, situation: Union[PathLike, Mapping[str, Any]],
                 kicks: Union[PathLike, Mapping[str, Any], KickModel, None] = None,
                 strategy: Optional[Strategy] = None, samples: Optional[int] = None,
                 coarse_rebounds: Optional[bool] = None, models: Optional[PathLike] = None) -> None: ...
    def decide(self, robot: RobotArg = None, ball: BallArg = None, seed: int = 1,
               strategy: Optional[Strategy] = None, samples: Optional[int] = None) -> Decision:
        """The decision for robot (Pose, dict or (x_m, y_m, theta_deg) in F; None: the
        situation's) and ball (Ball, dict or (x_m, y_m) in R; None: the situation's). The
        state is checked as a situation file's (on the carpet, sigmas >= 0)."""
    def decide_many(self, robots: npt.ArrayLike, balls: Optional[npt.ArrayLike] = None,
                    seed: Union[int, Sequence[int], npt.NDArray[np.uint64]] = 1,
                    strategy: Optional[Strategy] = None, samples: Optional[int] = None,
                    progress: Progress = None) -> Dict[str, Any]:
        """robots (N, 3) [x_m, y_m, theta_deg] in F; balls None or (N, 2) [x_m, y_m] in R; seed
        an int for every row or N ints. Returns kick_index (int32, -1: none), rotation_deg,
        trimmed_utility (float64), hypotheses (int64) and kick_names; row i equals
        decide(robots[i], balls[i], seed[i])."""

class CaseBase:
    """A case base (Ros et al. 2009) with the retrieval parameters, loaded once."""
    size: int  # stored cases, symmetric copies included
    def __init__(self, case_base: Optional[PathLike] = None, params: Optional[PathLike] = None,
                 models: Optional[PathLike] = None) -> None: ...
    def retrieve(self, problem: Union[PathLike, Mapping[str, Any]]) -> Json:
        """Retrieval for a problem (path, or dict with field, defending ("cyan"/"yellow"),
        ball {x_m, y_m}, teammates [{id, x_m, y_m, theta_deg}], opponents [{x_m, y_m}] in F):
        what `foresight cbr retrieve --json` prints."""

def models_dir(models: Optional[PathLike] = None) -> str:
    """The data folder the functions read (models/)."""

def load_situation(situation: PathLike, kicks: Optional[PathLike] = None,
                   models: Optional[PathLike] = None) -> Json:
    """A checked situation file: name, field_file, kicks_file, evaluation_file, kicks (names),
    samples, robot {x_m, y_m, theta_rad, sigma_*} in F, ball {x_m, y_m, sigma_*} in R,
    obstacles [{x_m, y_m, radius_m}]."""

def load_kick_model(file: PathLike) -> Json:
    """A checked kick-model file's content."""

def load_field(file: PathLike) -> Json:
    """A checked field file's content."""

def decide(situation: Union[PathLike, Mapping[str, Any]], strategy: Optional[Strategy] = None,
           samples: Optional[int] = None, seed: Optional[int] = None,
           kicks: Union[PathLike, Mapping[str, Any], KickModel, None] = None,
           models: Optional[PathLike] = None) -> Json:
    """What `foresight decide --json` prints (see Decision.to_dict). For many decisions build
    a Planner once instead."""

def simulate(situation: PathLike, kick: str, trials: Optional[int] = None,
             seed: Optional[int] = None, rotation_deg: Optional[float] = None,
             threads: Optional[int] = None, kicks: Optional[PathLike] = None,
             physics: Optional[PathLike] = None, models: Optional[PathLike] = None,
             base: Optional[str] = None, progress: Progress = None) -> Dict[str, Any]:
    """Physics trials of one kick: NumPy arrays, one entry per trial: rest_x_m, rest_y_m (F),
    time_s, launch_speed_mps, launch_direction_deg (intended robot frame), touched, launched,
    settled, fell, blocked (bool), max_tilt_deg, category, first_contact, status (int8 codes into
    category_names, contact_names, status_names), placement_dx_m, placement_dy_m,
    placement_dtheta_deg, speed_factor, carpet_factor, placement_redraws (int32). base:
    "fixed" or "floating"."""

def calibrate(robot: str, kick: Optional[str] = None, trials: Optional[int] = None,
              seed: Optional[int] = None, threads: Optional[int] = None,
              situation: Optional[PathLike] = None, kicks: Optional[PathLike] = None,
              physics: Optional[PathLike] = None, from_csv: Optional[PathLike] = None,
              confidence: Optional[float] = None, resamples: Optional[int] = None,
              models: Optional[PathLike] = None, base: Optional[str] = None,
              progress: Progress = None) -> Json:
    """Calibrates the robot's kicks (all, or `kick`) from physics or a CSV log: the report's
    calibration.json. base: "fixed" or "floating" (default: the physics file's, floating)."""

def fidelity(situations: Optional[str] = None, trials: Optional[int] = None,
             samples: Optional[int] = None, converged: Optional[int] = None,
             seed: Optional[int] = None, threads: Optional[int] = None,
             kicks: Optional[PathLike] = None, physics: Optional[PathLike] = None,
             models: Optional[PathLike] = None, base: Optional[str] = None,
             progress: Progress = None) -> Json:
    """The coarse model against physics on a situation set ("quick", "full" or a file): the
    report's fidelity.json. base: "fixed" or "floating" (default: the physics files', floating)."""

def cbr_retrieve(problem: Union[PathLike, Mapping[str, Any]],
                 case_base: Optional[PathLike] = None, params: Optional[PathLike] = None,
                 models: Optional[PathLike] = None) -> Json:
    """What `foresight cbr retrieve --json` prints for a problem (see CaseBase.retrieve)."""

def passing(config: Union[str, PathLike], team: Optional[str] = None,
            scenarios: Optional[Sequence[int]] = None, trials: Optional[int] = None,
            seed: Optional[int] = None, threads: Optional[int] = None, mirror: bool = False,
            physics: bool = False, kicks: Optional[PathLike] = None,
            models: Optional[PathLike] = None, progress: Progress = None,
            base: Optional[str] = None) -> Dict[str, Any]:
    """The passing experiment's trials in the match simulator: config "dg" or "2d" (or a
    file), team "reactive", "cbr" or "both", scenarios (1-based; None: all), trials per
    scenario. NumPy arrays, one entry per trial in play order: team (int8 code into
    team_names), scenario, trial (int32), outcome (int8 code into outcome_names: goal, close,
    block, out, penalty_area, timeout), to_goal (bool), time_s (simulated), attacker_kicks,
    opponent_touches, shots_on_target, shots_saved, contests_resolved (the referee set down a
    ball both teams fought over too long), grabs_failed, kicks_missed,
    kicks_not_settled, kicks_fell, kicks_blocked (int32; the last four count physics kicks
    that did not end ok). base: "fixed" or "floating", with physics=True."""
