#!/usr/bin/env python3
"""Where the opponents win the ball against the CBR team: each opponent touch, grab and steal of a
passing run (`foresight experiment passing --out DIR`) attributed to what the attackers were doing
then, read from the team's own messages in passing_<team>_events.csv:

  case      between a "cbr case" message and the cycle's abort, end or next coordinator;
  default   otherwise (idle after "no case" or an abort, waiting for a cycle): the default behaviour.

For the reactive team every event is "default". Prints, per scenario, the opponents' events per
trial and per minute of play in each state, and the share of trial time in each state; then the
cases most often given up for a lost ball, with how often their getter kicked at all.

usage: defender_contacts.py RUN_DIR [cbr|reactive]
"""
import csv
import collections
import sys


def main():
    run = sys.argv[1]
    team = sys.argv[2] if len(sys.argv) > 2 else "cbr"
    events = collections.defaultdict(lambda: collections.Counter())
    time_in = collections.defaultdict(lambda: collections.Counter())
    trials = collections.Counter()
    key = None
    state, since, last_t = "default", 0.0, 0.0
    cases = collections.defaultdict(collections.Counter)  # (scenario, case) -> counts
    case, kicked = None, False

    def close(k, t):
        if k is not None:
            time_in[k[0]][state] += t - since

    with open(f"{run}/passing_{team}_events.csv") as f:
        for row in csv.DictReader(f):
            if row["event"] == "":
                continue
            k = (int(row["scenario"]), int(row["trial"]))
            t = float(row["time_s"])
            if k != key:
                close(key, last_t)
                key, state, since = k, "default", 0.0
                trials[k[0]] += 1
            last_t = t
            detail = row["detail"]
            if row["event"] == "message" and detail.startswith("cbr "):
                kind = detail.split()[1]
                new = state
                if kind == "case":
                    new = "case"
                    case, kicked = (k[0], detail.split()[4]), False
                    cases[case]["retrieved"] += 1
                elif kind in ("abort", "end", "no_case", "coordinator"):
                    new = "default"
                    if case is not None and kind == "abort":
                        cases[case]["aborted " + detail.split()[4]] += 1
                    case = None
                if new != state:
                    time_in[k[0]][state] += t - since
                    state, since = new, t
            elif row["robot"] in ("A", "B") and row["event"] == "kick" and case is not None:
                if not kicked:
                    cases[case]["first kicks"] += 1
                kicked = True
            elif row["robot"] not in ("A", "B", "") and row["event"] in ("touch", "grab", "steal"):
                events[k[0]][state] += 1
                if case is not None and not kicked:
                    cases[case]["opponent events before the first kick"] += 1
    close(key, last_t)
    print(f"{team}: opponents' touches, grabs and steals per trial and per minute of play in each state")
    print("scn  state    share of time   per trial  per min")
    for s in sorted(trials):
        n = trials[s]
        total = sum(time_in[s].values())
        for st in ("case", "default"):
            secs = time_in[s][st]
            e = events[s][st]
            per_min = e / (secs / 60.0) if secs > 0 else float("nan")
            print(f"{s:3d}  {st:8s} {100.0 * secs / total:6.1f} %        {e / n:6.2f}  {per_min:6.2f}")
    print("the ten cases most often given up for a lost ball (scenario, case: counts)")
    worst = sorted(cases.items(), key=lambda kv: -kv[1]["aborted ball_lost"])[:10]
    for (s, name), c in worst:
        print(f"  {s} {name}: " + ", ".join(f"{k} {v}" for k, v in sorted(c.items())))


if __name__ == "__main__":
    main()
