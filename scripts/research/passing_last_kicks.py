#!/usr/bin/env python3
"""Which kick ended each trial of a passing run: the last kick before the trial's end, by robot and
kick, whether a case was being played when it was kicked, and where the ball was.

A research aid for the CBR team (how outs and goals come about), reading a run folder of
`foresight experiment passing` (passing_<team>_events.csv).

usage: passing_last_kicks.py RUN_DIR [TEAM ...]     (default teams: cbr reactive)
"""
import collections
import csv
import sys


def trials(path):
    """(scenario, trial) -> list of event rows, in order."""
    out = collections.OrderedDict()
    with open(path) as f:
        for row in csv.DictReader(f):
            out.setdefault((int(row["scenario"]), int(row["trial"])), []).append(row)
    return out


def last_kick(events):
    in_case = False
    last = None
    for e in events:
        if e["event"] == "message" and e["detail"].startswith("cbr "):
            word = e["detail"].split()[1]
            if word == "case":
                in_case = True
            elif word in ("abort", "end", "no_case", "coordinator"):
                in_case = False
        elif e["event"] == "kick":
            last = (e["robot"], e["detail"], in_case, float(e["ball_x_m"]), float(e["ball_y_m"]))
    return last


def main(run_dir, *teams):
    for team in teams or ("cbr", "reactive"):
        table = collections.Counter()
        for (scenario, _), events in trials(f"{run_dir}/passing_{team}_events.csv").items():
            end = events[-1]["detail"] if events[-1]["event"] == "end" else "?"
            k = last_kick(events)
            if k is None:
                table[(scenario, end, "-", "-", "-")] += 1
                continue
            robot, kick, in_case, x, _ = k
            side = "att" if robot in ("A", "B") else "opp"
            zone = "own half" if x < 0 else ("far half" if x < 1.9 else "near goal")
            table[(scenario, end, side + " " + kick, "case" if in_case else "no case", zone)] += 1
        print(f"== {team}: trial end, last kick, in a case, ball x when kicked (count)")
        for key, n in sorted(table.items(), key=lambda kv: (kv[0][0], -kv[1])):
            print(f"  s{key[0]} {key[1]:8s} {key[2]:22s} {key[3]:8s} {key[4]:10s} {n}")


if __name__ == "__main__":
    main(*sys.argv[1:])
