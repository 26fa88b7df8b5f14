#!/usr/bin/env python3
"""When each team's attackers first kick in a passing run, per scenario: the mean time of the
first attacker kick (the events CSV's "kick" rows by A or B) and of the first opponent touch, and
how often the opponents touch the ball before the attackers' first kick: a research aid for the
CBR team's pace against the reactive team's (issue 44). usage: first_kicks.py RUN_DIR"""
import csv
import sys
from collections import defaultdict
from pathlib import Path
from statistics import mean


def summary(path):
    first_kick, first_opp = {}, {}
    trials = set()
    with path.open() as f:
        for row in csv.DictReader(f):
            key = (row["scenario"], row["trial"])
            trials.add(key)
            t = float(row["time_s"])
            if row["event"] == "kick" and row["robot"] in ("A", "B"):
                first_kick.setdefault(key, t)
            if row["event"] in ("touch", "grab", "kick") and row["robot"] not in ("A", "B"):
                first_opp.setdefault(key, t)
    out = defaultdict(lambda: [[], [], 0, 0])
    for key in trials:
        s = out[key[0]]
        s[3] += 1
        if key in first_kick:
            s[0].append(first_kick[key])
        if key in first_opp:
            s[1].append(first_opp[key])
        if first_opp.get(key, 1e9) < first_kick.get(key, 1e9):
            s[2] += 1
    return out


def main(folder):
    for team in ("cbr", "reactive"):
        path = Path(folder) / f"passing_{team}_events.csv"
        if not path.exists():
            continue
        for scn, (kicks, opps, opp_first, n) in sorted(summary(path).items()):
            print(f"{team:8s} s{scn}: first attacker kick {mean(kicks):5.2f} s ({len(kicks)} of {n}),"
                  f" first opponent touch {mean(opps) if opps else float('nan'):5.2f} s,"
                  f" opponent first in {opp_first} of {n}")


if __name__ == "__main__":
    main(sys.argv[1])
