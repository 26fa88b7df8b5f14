#!/usr/bin/env python3
"""Markdown tables for docs/EXPERIMENTS.md from `foresight experiment passing --team both` output
folders: the world check (the reactive team against the paper's reactive rows), the claims
tally, the outcomes with who caused them, and the reactive team's back-ups (Table 2). Reads only what the run wrote (scorecard.json, passing_<team>.json,
passing_<team>_trials.csv); computes nothing the tool does not, except the share of outs whose
last touch was an attacker's, counted from the trials CSV.

usage: passing_tables.py DIR [DIR ...]   (passing folders, one per configuration, and
                                          `experiment ablations` folders)
"""
import csv
import json
import sys
from pathlib import Path

TEAMS = ("cbr", "reactive")
ATTACKERS = ("A", "B")  # the robots last_touch names on the attacking side


def world_check(card):
    w = card["world_check"]
    print(f"{card['config'].upper()}, goalie {card['goalie']}: {w['scenarios_agreeing']} of "
          f"{len(w['scenarios'])} scenarios agree (the paper's {w['team']} value inside our "
          f"interval or within {w['within_points']:g} points)")
    print()
    print("| scn | measure | paper | ours | our 95 % interval | verdict |")
    print("| --- | --- | --- | --- | --- | --- |")
    for s in w["scenarios"]:
        for c in s["cells"]:
            if c["ours"] is None:
                continue
            share = c["column"].endswith("%")
            ours = f"{c['ours']:.1f}" if share else f"{c['ours']:.2f}"
            ci = (f"[{c['ours_ci'][0]:.1f}, {c['ours_ci'][1]:.1f}]" if share else
                  f"[{c['ours_ci'][0]:.2f}, {c['ours_ci'][1]:.2f}]") if c["ours_ci"] else "-"
            name = f"**{c['column']}**" if c["decides"] else c["column"]
            print(f"| {s['scenario']} | {name} | {c['paper']:g} | {ours} | {ci} | {c['verdict']} |")
        print(f"| {s['scenario']} | **scenario** | | | | {s['verdict']} |")
    print()


def claims(cards):
    print("| claim | " + " | ".join(c["config"].upper() for c in cards) + " |")
    print("| --- |" + " --- |" * len(cards))
    for i, claim in enumerate(cards[0]["claims"]):
        cells = []
        for card in cards:
            c = card["claims"][i]
            n = len(c["scenarios"])
            cells.append(f"{c['holds']} of {n} (opposite {c['opposite']})")
        print(f"| {claim['name']} | " + " | ".join(cells) + " |")


def outs_by_attackers(folder, team):
    counts = {}
    with open(folder / f"passing_{team}_trials.csv") as f:
        for row in csv.DictReader(f):
            if row["outcome"] != "out":
                continue
            n, a = counts.get(row["scenario"], (0, 0))
            counts[row["scenario"]] = (n + 1, a + (row["last_touch"] in ATTACKERS))
    return counts


def outcomes(folder, card):
    print("| cfg | scn | team | goal | close | block | out (attackers last) | p. area | to goal "
          "| by the attackers | timeout / cap | opp. touches | time (s) | shots on target, saved "
          "| opp. kicks >= 0.3 m, towards own goal | contests ended | local game stuck |")
    print("| --- " * 17 + "|")
    for team in TEAMS:
        run = json.loads((folder / f"passing_{team}.json").read_text())
        outs = outs_by_attackers(folder, team)
        for s in run["scenarios"]:
            o = s["outcomes"]
            pct = lambda k: f"{100 * o[k]['share']:.1f}" if k in o else "-"
            n_out, by_att = outs.get(str(s["scenario"]), (0, 0))
            c = s["causes"]
            touches = " / ".join(f"{v['mean']:.2f}" for v in s["possession"].values())
            print(f"| {card['config'].upper()} | {s['scenario']} | {team} | {pct('goal')} | "
                  f"{pct('close')} | {pct('block')} | {pct('out')} ({by_att} of {n_out}) | "
                  f"{pct('penalty_area')} | {100 * s['to_goal']['share']:.1f} | "
                  f"{100 * c['to_goal_by_attackers']['share']:.1f} | {pct('timeout')} | {touches} | "
                  f"{s['time_s']['mean']:.1f} | {c['shots_on_target']}, {c['shots_saved']} | "
                  f"{c['opponent_kicks_moved']}, {c['opponent_kicks_towards_own_goal']} | "
                  f"{c['contests_resolved_per_trial']:.2f} | {c['stuck_penalties']} |")


def backups(card):
    for t in card["tables"]:
        if t["table"] != 2:
            continue
        print("| scn | " + " | ".join(c["column"] + " (paper / ours)" for c in t["rows"][0]["cells"]) + " |")
        print("| --- |" + " --- |" * len(t["rows"][0]["cells"]))
        for r in t["rows"]:
            print(f"| {r['scenario']} | " + " | ".join(
                f"{c['paper']:g} / {c['ours']:.2f}" for c in r["cells"]) + " |")


def cbr_play(cards):
    print("| cfg | scn | default play (robot time; of it ball rolling, opponent on it) | two-kick cases played to the end | all cases "
          "played to the end | wait-end safety net | no case per trial |")
    print("| --- " * 7 + "|")
    for card in cards:
        for r in card.get("cbr_play", []):
            lo, hi = r["multi_kick_completed_share_ci"]
            print(f"| {card['config'].upper()} | {r['scenario']} | "
                  f"{100 * r['default_time_share']:.1f} % ("
                  f"{100 * r.get('default_time_share_ball_rolling', 0):.1f}, "
                  f"{100 * r.get('default_time_share_opponent_on_ball', 0):.1f}) | "
                  f"{r['cases_multi_kick_completed']} of "
                  f"{r['cases_multi_kick']}, {100 * r['multi_kick_completed_share']:.1f} % "
                  f"[{100 * lo:.1f}, {100 * hi:.1f}] | {r['cases_completed']} of "
                  f"{r['cases_retrieved']} | {r['wait_end_timeouts']} | "
                  f"{r['no_case'] / r['trials']:.2f} |")
    print()


def ablations(folder):
    run = json.loads((folder / "ablations.json").read_text())
    dg = any(v["scenarios"][0]["block"] > 0 for v in run["variants"])
    cells = "to goal % / out % / block % / timeout %" if dg else "to goal % / out % / timeout %"
    print(f"{run['params']['config']}, {run['params']['trials_per_scenario']} trials: {cells}; "
          "**bold**: the paired to-goal difference against the paper's team excludes 0")
    print()
    print("| # | variant | " + " | ".join(f"scenario {r['scenario']}" for r in run["reactive"]) + " |")
    print("| --- | --- |" + " --- |" * len(run["reactive"]))
    print("| 0 | reactive | " + " | ".join(
        f"{100 * r['to_goal']:.1f} / {100 * r['out']:.0f}" for r in run["reactive"]) + " |")
    for i, v in enumerate(run["variants"], start=1):
        row = []
        for s in v["scenarios"]:
            d = s["difference_vs_paper"]["to_goal"]["ci"]
            goal = f"{100 * s['to_goal']['share']:.1f}"
            if d[0] > 0 or d[1] < 0:
                goal = f"**{goal}**"
            parts = [goal, f"{100 * s['out']:.0f}"] + ([f"{100 * s['block']:.0f}"] if dg else [])
            row.append(" / ".join(parts + [f"{100 * s['timeout']:.0f}"]))
        print(f"| {i} | {v['name']} | " + " | ".join(row) + " |")
    print()


def main(folders):
    folders = [Path(f) for f in folders]
    for f in [f for f in folders if (f / "ablations.json").exists()]:
        ablations(f)
    folders = [f for f in folders if (f / "scorecard.json").exists()]
    if not folders:
        return
    cards = [json.loads((f / "scorecard.json").read_text()) for f in folders]
    for card in cards:
        world_check(card)
    claims(cards)
    print()
    cbr_play(cards)
    for folder, card in zip(folders, cards):
        outcomes(folder, card)
        print()
    for card in cards:
        backups(card)


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
