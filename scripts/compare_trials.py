#!/usr/bin/env python3
"""Compares two `foresight simulate --json` runs of the same kick and seed trial by trial: an
old binary's and a new one's (docs/PHYSICS.md, "The watch after the launch", is what it was
written for). Prints one line per run pair:

  the trials whose ball (rest, category, first contact, time, launch, draw) is the same to the
  last bit; the trials whose category changed; the trials whose fall changed (fell in one run and
  not in the other); the falls in each run; the largest tilt over all trials in each run and its
  margin to the fall tilt; the largest change of a trial's largest tilt; and, when balls differ,
  whether the new run's mean launch speed and direction lie in the old run's 95 % t intervals.

Exits 1 when a category or a fall changed.

Usage: scripts/compare_trials.py FALL_TILT_DEG OLD.json NEW.json [OLD2.json NEW2.json ...]
"""
import json
import math
import statistics
import sys

BALL_KEYS = ("rest_m", "category", "first_contact", "time_s", "touched", "launched", "settled",
             "blocked", "launch_speed_mps", "launch_direction_deg", "draw")
T975 = 1.962  # Student t, 97.5 %, ~1000 trials


def mean_interval(values):
    m = statistics.fmean(values)
    half = T975 * statistics.stdev(values) / math.sqrt(len(values))
    return m, m - half, m + half


def compare(fall_tilt_deg, old_file, new_file):
    old = json.load(open(old_file))
    new = json.load(open(new_file))
    # Trial i draws from stream i of the seed, so the first trials of a longer run are a shorter
    # run's trials: the shorter run's are compared.
    n = min(len(old["trials_detail"]), len(new["trials_detail"]))
    a, b = old["trials_detail"][:n], new["trials_detail"][:n]
    same = sum(all(x[k] == y[k] for k in BALL_KEYS) for x, y in zip(a, b))
    category = sum(x["category"] != y["category"] for x, y in zip(a, b))
    falls = sum(x["fell"] != y["fell"] for x, y in zip(a, b))
    tilt_a = [x["max_tilt_deg"] for x in a]
    tilt_b = [y["max_tilt_deg"] for y in b]
    d_tilt = max(abs(p - q) for p, q in zip(tilt_a, tilt_b))
    line = (f"{new['robot']} {new['kick']}: {len(a)} trials, ball same bits {same}, category changed "
            f"{category}, fall changed {falls}, falls old {sum(x['fell'] for x in a)} new "
            f"{sum(y['fell'] for y in b)}, max tilt old {max(tilt_a):.3f} new {max(tilt_b):.3f} deg "
            f"(margin to {fall_tilt_deg:g}: {fall_tilt_deg - max(tilt_b):.2f}), largest tilt "
            f"change {d_tilt:.3g} deg")
    if same < len(a):
        for key in ("launch_speed_mps", "launch_direction_deg"):
            old_v = [x[key] for x in a if x["launched"]]
            new_v = [y[key] for y in b if y["launched"]]
            m, lo, hi = mean_interval(old_v)
            n = statistics.fmean(new_v)
            line += f"; {key} old {m:.4f} [{lo:.4f}, {hi:.4f}] new {n:.4f} {'in' if lo <= n <= hi else 'OUT'}"
    print(line)
    return category == 0 and falls == 0


def main(argv):
    if len(argv) < 4 or len(argv) % 2 != 0:
        print(__doc__, file=sys.stderr)
        return 2
    fall_tilt_deg = float(argv[1])
    ok = True
    for i in range(2, len(argv), 2):
        ok = compare(fall_tilt_deg, argv[i], argv[i + 1]) and ok
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
