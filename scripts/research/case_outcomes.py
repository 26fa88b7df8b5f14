#!/usr/bin/env python3
"""How each retrieved case's cycle ended, per scenario: played to the end (END), aborted (by
reason) or superseded by a newer cycle without either, from a passing run's events CSV (the CBR
team's messages: "cbr case cycle N NAME", "cbr abort cycle N REASON", "cbr end cycle N").
A research aid for the CBR team (issue 44). usage: case_outcomes.py RUN_DIR [SCENARIO]"""
import csv
import re
import sys
from collections import Counter, defaultdict
from pathlib import Path

CASE = re.compile(r"cbr case cycle (\d+) (\S+)")
ABORT = re.compile(r"cbr abort cycle (\d+) (\S+)")
END = re.compile(r"cbr end cycle (\d+)")


def main(folder, only=None):
    path = Path(folder) / "passing_cbr_events.csv"
    if not path.exists():
        path = Path(folder) / "passing_events.csv"
    # (scenario, trial, cycle) -> case name, and how it ended (the first message that says).
    case_of, ended = {}, {}
    with path.open() as f:
        for row in csv.DictReader(f):
            if row["event"] != "message" or (only and row["scenario"] != only):
                continue
            key = (row["scenario"], row["trial"])
            d = row["detail"]
            if m := CASE.match(d):
                case_of.setdefault(key + (m[1],), m[2])
            elif m := ABORT.match(d):
                ended.setdefault(key + (m[1],), "abort " + m[2])
            elif m := END.match(d):
                ended.setdefault(key + (m[1],), "end")
    table = defaultdict(Counter)
    for k, name in case_of.items():
        table[(k[0], name)][ended.get(k, "superseded or trial over")] += 1
    for (scenario, name), c in sorted(table.items(), key=lambda x: (x[0][0], -sum(x[1].values()))):
        total = sum(c.values())
        parts = ", ".join(f"{how} {n}" for how, n in c.most_common())
        print(f"s{scenario} {name:40s} {total:5d}: {parts}")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else None)
