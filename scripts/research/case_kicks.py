#!/usr/bin/env python3
"""Every kick and pass of the hand-written case base (models/cases/*.json) with where it starts
(the ball where its kicker holds it: the case's ball, or the receiver's position), where it
aims and how long it is, and whether it shoots at the goal: a research aid for writing cases
(which shots are taken from how far). usage: case_kicks.py [CASE_DIR]"""
import json
import math
import sys
from pathlib import Path

GOAL_X_M = 2.7  # the Four-Legged field's goal line (models/fields/four_legged.json)


def kicks_of(case):
    ball = (case["ball"]["x_m"], case["ball"]["y_m"])
    pos = {t["id"]: (t["x_m"], t["y_m"]) for t in case["teammates"]}
    # Follow the ball: after a pass it lies at the receiver's spot.
    at = ball
    rows = []
    for t in case["teammates"]:
        for a in t["actions"]:
            if a["type"] == "dribble":
                at = (a["target"]["x_m"], a["target"]["y_m"])
    order = []  # (kicker id, action) in ball order: getter first, then each receiver
    mates = {t["id"]: t for t in case["teammates"]}
    holder = next(t["id"] for t in case["teammates"] if t["actions"][0]["type"] == "get_ball")
    at = ball
    seen = set()
    while holder is not None and holder not in seen:
        seen.add(holder)
        nxt = None
        for a in mates[holder]["actions"]:
            if a["type"] == "dribble":
                at = (a["target"]["x_m"], a["target"]["y_m"])
            if a["type"] == "pass":
                to = pos[a["to"]]
                rows.append((case["name"], holder, a["kick"], at, to, False))
                at, nxt = to, a["to"]
                break
            if a["type"] == "kick":
                if a.get("at") == "goal":
                    to, goal = (GOAL_X_M, 0.0), True
                else:
                    to = (a["target"]["x_m"], a["target"]["y_m"])
                    goal = abs(to[0]) >= GOAL_X_M - 1e-9 and abs(to[1]) <= 0.4
                rows.append((case["name"], holder, a["kick"], at, to, goal))
                break
        holder = nxt
    return rows


def main(folder):
    for f in sorted(Path(folder).glob("*.json")):
        if f.name == "case_base.json":
            continue
        for name, who, kick, a, b, goal in kicks_of(json.loads(f.read_text())):
            d = math.dist(a, b)
            print(f"{name:24s} t{who} {kick:16s} ({a[0]:5.2f},{a[1]:5.2f}) -> ({b[0]:5.2f},{b[1]:5.2f})"
                  f" {d:4.2f} m{'  SHOT' if goal else ''}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "models/cases")
