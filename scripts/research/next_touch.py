#!/usr/bin/env python3
"""Who touches the ball next after each attacker kick: per scenario, kick and the case it was
kicked in ("default" outside a case), how often an attacker touched the ball next, how often an
opponent did, and how often the trial ended first (and how). It shows which kicks keep the ball
for the team and which give it to the opponents, from a passing run's events CSV. A research aid
for the CBR team. usage: next_touch.py RUN_DIR [ROWS]     (default 30 rows per team)"""
import collections
import csv
import re
import sys
from pathlib import Path

ATTACKERS = ("A", "B")


def trials(path):
    out = collections.OrderedDict()
    with path.open() as f:
        for row in csv.DictReader(f):
            out.setdefault((row["scenario"], row["trial"]), []).append(row)
    return out


def next_touches(path):
    """(scenario, kick, case) -> Counter of 'att', 'opp' and 'end:OUTCOME'."""
    stat = collections.defaultdict(collections.Counter)
    for (scenario, _), rows in trials(path).items():
        case, pending = None, None
        for r in rows:
            d = r["detail"]
            if r["event"] == "message":
                if m := re.match(r"cbr case cycle \d+ (\S+)", d):
                    case = m[1].split("/")[0]
                elif re.match(r"cbr (abort|end|no_case)", d):
                    case = None
                continue
            who = "att" if r["robot"] in ATTACKERS else ("opp" if r["robot"] else None)
            if r["event"] in ("touch", "grab", "steal") and pending and who:
                stat[pending][who] += 1
                pending = None
            if r["event"] == "kick" and who == "att":
                pending = (f"s{scenario}", d, case or "default")
            if r["event"] == "end" and pending:
                stat[pending]["end:" + d] += 1
                pending = None
    return stat


def main(folder, rows=30):
    for team in ("cbr", "reactive"):
        path = Path(folder) / f"passing_{team}_events.csv"
        if not path.exists():
            continue
        stat = next_touches(path)
        for key, c in sorted(stat.items(), key=lambda kv: -sum(kv[1].values()))[:rows]:
            n = sum(c.values())
            ends = {k[4:]: v for k, v in c.items() if k.startswith("end:")}
            print(f"{team:8s} {key[0]:3s} {key[1]:16s} {key[2]:24s} kicks {n:5d}  attacker next "
                  f"{c['att'] / n:4.2f}  opponent next {c['opp'] / n:4.2f}  trial ended {ends}")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 30)
