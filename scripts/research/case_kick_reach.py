#!/usr/bin/env python3
"""How far each shipped case asks its kicks to carry the ball, against what the kick carries.

A research aid for the CBR team's cases (not the check itself, which belongs in `foresight cbr
check`). The ball path follows cbr/free_path.h in the case's own situation: it starts at the
case's ball with the first teammate whose first action is get_ball; a dribble moves the ball to
its target; a kick goes to its target or, "at": "goal", to the attacked goal's centre; a pass goes
to the receiver's position (or the go_to target before its receive) and the walk continues with
the receiver. Reach: the rest distance of a launch speed two sd above the mean,
d = (v + 2 s)^2 / (2 a) (planner/ball_roll.h); about 2.3 % of kicks roll further.

usage: case_kick_reach.py [KICK_MODEL] [CASES_DIR]
       (defaults: models/kicks/aibo_ers7_published.json, the match's default, and models/cases)
"""
import glob
import json
import math
import sys

REACH_SIGMAS = 2.0  # assumption: a case may ask for a roll that 1 kick in 40 exceeds


def load_kicks(path):
    model = json.load(open(path))
    a = model["rolling_deceleration_mps2"]
    kicks = {}
    for k in model["kicks"]:
        mean_m = (k["speed_mps"] ** 2 + k["sigma_speed_mps"] ** 2) / (2 * a)
        reach_m = (k["speed_mps"] + REACH_SIGMAS * k["sigma_speed_mps"]) ** 2 / (2 * a)
        kicks[k["name"]] = (mean_m, reach_m)
    return kicks


def point(p):
    return (p["x_m"], p["y_m"])


def receiver_spot(receiver):
    spot = point(receiver)
    for action in receiver["actions"]:
        if action["type"] == "receive":
            break
        if action["type"] == "go_to":
            spot = point(action["target"])
    return spot


def kicks_of(case, goal_x_m):
    """(kind, kick, length) along the case's ball path."""
    mates = {t["id"]: t for t in case["teammates"]}
    robot = next(t for t in case["teammates"] if t["actions"] and t["actions"][0]["type"] == "get_ball")
    ball = point(case["ball"])
    seen = set()
    while robot is not None and robot["id"] not in seen:
        seen.add(robot["id"])
        following = None
        for action in robot["actions"]:
            if action["type"] == "dribble":
                ball = point(action["target"])
            elif action["type"] == "kick":
                end = (goal_x_m, 0.0) if action.get("at") == "goal" else point(action["target"])
                yield "kick", action["kick"], math.dist(ball, end)
                ball = end
            elif action["type"] == "pass":
                following = mates[action["to"]]
                end = receiver_spot(following)
                yield "pass", action["kick"], math.dist(ball, end)
                ball = end
                break
        robot = following


def main(kick_file="models/kicks/aibo_ers7_published.json", cases_dir="models/cases"):
    kicks = load_kicks(kick_file)
    base = json.load(open(f"{cases_dir}/case_base.json"))
    field = json.load(open(f"models/fields/{base['field']}.json"))
    goal_x_m = 0.5 * field["field_length_m"]  # the attacked goal line (cases defend cyan)
    beyond = total = 0
    for path in sorted(glob.glob(f"{cases_dir}/*.json")):
        case = json.load(open(path))
        if "teammates" not in case:
            continue
        for kind, kick, length_m in kicks_of(case, goal_x_m):
            mean_m, reach_m = kicks[kick]
            total += 1
            beyond += length_m > reach_m
            print(f"{case['name']:22s} {kind:4s} {kick:16s} {length_m:5.2f} m  mean roll {mean_m:4.2f}"
                  f"  reach {reach_m:4.2f}{'  BEYOND' if length_m > reach_m else ''}")
    print(f"{beyond} of {total} kicks and passes beyond reach ({kick_file})")


if __name__ == "__main__":
    main(*sys.argv[1:])
