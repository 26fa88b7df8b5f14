"""A sweep of decisions from Python over in-memory poses against the same decisions in C++.

The scene and poses are the planner benchmarks' (bench/bench_scenes.h, printed by
planner_poses): the SPL field, the NAO kicks, one obstacle, 16 poses all over the field with the
paper's uncertainty; decision i is for pose i mod 16 with seed i and 30 samples, as
BM_Decision in planner_bench makes them (a kept evaluator and Decision: the robot's cycle).
From Python a Planner is built once, then
  loop:  planner.decide(robot=Pose, ball=Ball, seed=i) 1000 times (a Decision object each), and
  array: planner.decide_many(robots (1000, 3), balls (1000, 2), seed=seeds) once.
Each is timed 5 times; the medians per decision are printed beside planner_bench's medians of
BM_Decision for the same strategy, from one run, with their ratio. For comparison, the last
column times foresight.decide(FILE) (reads the files and builds the planner every call) on the
scene with the first pose, 200 calls.

Usage: PYTHONPATH=BUILD/python python3 bench/python_decision_sweep.py [BUILD]
"""
import json
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import foresight

BUILD = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "build")
DECISIONS = 1000
REPETITIONS = 5
SAMPLES = 30
STRATEGIES = {"naoth": "plain_naoth", "optimal_all": "optimal_all"}  # Python -> BM_Decision


def cpp_medians_us():
    """planner_bench's median of BM_Decision per strategy, in microseconds."""
    pattern = "|".join(STRATEGIES.values())
    done = subprocess.run(
        [str(BUILD / "bench" / "planner_bench"), f"--benchmark_filter=BM_Decision/({pattern})$",
         f"--benchmark_repetitions={REPETITIONS}", "--benchmark_report_aggregates_only=true",
         "--benchmark_format=json"], capture_output=True, text=True, check=True)
    medians = {}
    for run in json.loads(done.stdout)["benchmarks"]:
        if run.get("aggregate_name") == "median":
            assert run["time_unit"] == "us"
            medians[run["run_name"].split("/", 1)[1]] = run["real_time"]
    return medians


def median_per_decision_us(sweep, decisions=DECISIONS):
    times = []
    for _ in range(REPETITIONS):
        start = time.perf_counter()
        sweep()
        times.append((time.perf_counter() - start) / decisions * 1e6)
    return statistics.median(times)


def main():
    scene = json.loads(subprocess.run([str(BUILD / "bench" / "planner_poses")],
                                      capture_output=True, text=True, check=True).stdout)
    poses = scene.pop("poses")
    robots = [foresight.Pose(**p["robot"]) for p in poses]
    balls = [foresight.Ball(**p["ball"]) for p in poses]
    robot_rows = np.array([[poses[i % 16]["robot"][k] for k in ("x_m", "y_m", "theta_deg")]
                           for i in range(DECISIONS)])
    ball_rows = np.array([[poses[i % 16]["ball"][k] for k in ("x_m", "y_m")]
                          for i in range(DECISIONS)])
    seeds = np.arange(DECISIONS, dtype=np.uint64)
    cpp = cpp_medians_us()
    print(f"{DECISIONS} decisions per sweep, {SAMPLES} samples, median of {REPETITIONS} sweeps, "
          f"microseconds per decision")
    print(f"{'strategy':<12} {'C++':>8} {'Python loop':>12} {'ratio':>6} "
          f"{'decide_many':>12} {'ratio':>6} {'decide(FILE)':>13}")
    first = dict(scene, robot=poses[0]["robot"], ball=poses[0]["ball"])
    file = pathlib.Path(tempfile.mkdtemp()) / "bench_scene.json"
    file.write_text(json.dumps(first))
    for strategy, bench_name in STRATEGIES.items():
        # The situation's own belief is the first pose's; every pose brings its own sigmas.
        planner = foresight.Planner(dict(scene, robot=poses[0]["robot"], ball=poses[0]["ball"]),
                                    strategy=strategy, samples=SAMPLES)
        decide = planner.decide

        def loop():
            for i in range(DECISIONS):
                decide(robot=robots[i & 15], ball=balls[i & 15], seed=i)

        def array():
            planner.decide_many(robot_rows, ball_rows, seed=seeds)

        # The two ways agree (the poses' sigmas are all the situation's).
        many = planner.decide_many(robot_rows[:16], ball_rows[:16], seed=seeds[:16])
        assert [decide(robot=robots[i], ball=balls[i], seed=i).kick_index
                for i in range(16)] == list(many["kick_index"])
        def from_file():
            for i in range(200):
                foresight.decide(file, strategy=strategy, samples=SAMPLES, seed=i)

        py_loop, py_array = median_per_decision_us(loop), median_per_decision_us(array)
        py_file = median_per_decision_us(from_file, 200)
        c = cpp[bench_name]
        print(f"{strategy:<12} {c:8.2f} {py_loop:12.2f} {py_loop / c:6.2f} {py_array:12.2f} "
              f"{py_array / c:6.2f} {py_file:13.1f}")


if __name__ == "__main__":
    main()
