#!/usr/bin/env python3
"""Each hand-written case in its own situation: the CBR team against the reactive team from the
case's problem (its ball, its robots, its opponents), as a passing scenario, the same random
numbers for both teams. It answers "does the team play better than its default where this case
applies?" for every case, on situations the shipped scenarios do not hold. A research aid for
writing cases. usage: case_duels.py OUT_DIR [TRIALS] [SEED] [CASE ...]

The scenario of a case (assumptions, no source: the cases give no second attacker and leave out
opponents far from the ball):
- attacker 1 stands where the case's robot 1 stands, attacker 2 where its robot 2 stands; an
  individual case's second attacker stands SUPPORT_BACK_M behind the ball and SUPPORT_SIDE_M
  towards the field's middle (the shipped scenarios' support, e.g. dg_2: 0.2 m back, 1.0 m in), further back by 0.1 m
  steps while it would stand on an opponent the case places;
- every opponent the case names starts where the case puts it (the one whose region holds it),
  moved into its home region if outside; an opponent the case leaves out waits as the shipped
  scenarios' opponents do: on its region's boundary nearest the ball, or, with the ball inside
  its region, FRONT_GAP_M in front of the ball towards the goal (inside its region);
- everyone faces the ball.
A case named *_2d plays in the 2D configuration, *_dg or with a goalie in the DG one, a case
with no opponent in both. The table: per case and configuration, the case the CBR team
retrieved first (how often), goal and to-goal shares of both teams and the paired difference of
to goal with its 95 % interval (passing_comparison.json), and outs."""
import collections
import csv
import json
import math
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MODELS = ROOT / "models"
FORESIGHT = ROOT / "build" / "app" / "foresight"
SUPPORT_BACK_M = 0.2
SUPPORT_SIDE_M = 1.0
FRONT_GAP_M = 1.0
CLEAR_M = 0.3  # two robot radii (0.12 m, models/match/aibo_ers7.json) and a margin
HALF_WIDTH_M = 1.8  # models/fields/four_legged.json: field_width_m 3.6


def clamp(v, lo, hi):
    return max(lo, min(hi, v))


def inside(region, p):
    return (region["x_min_m"] <= p[0] <= region["x_max_m"]
            and region["y_min_m"] <= p[1] <= region["y_max_m"])


def into(region, p):
    return (clamp(p[0], region["x_min_m"], region["x_max_m"]),
            clamp(p[1], region["y_min_m"], region["y_max_m"]))


def waiting(region, ball, others):
    """The wait spot, or the region's point nearest it clear of every robot already placed."""
    want = into(region, ball) if not inside(region, ball) else into(
        region, (ball[0] + FRONT_GAP_M, ball[1]))
    grid = [(region["x_min_m"] + 0.05 * i, region["y_min_m"] + 0.05 * j)
            for i in range(int((region["x_max_m"] - region["x_min_m"]) / 0.05) + 1)
            for j in range(int((region["y_max_m"] - region["y_min_m"]) / 0.05) + 1)]
    clear = [p for p in [want] + grid
             if all(math.dist(p, o) >= CLEAR_M for o in others) and math.dist(p, ball) >= CLEAR_M]
    return min(clear, key=lambda p: math.dist(p, want))


def facing(p, ball):
    return round(math.degrees(math.atan2(ball[1] - p[1], ball[0] - p[0])), 1)


def configs_of(case):
    name = case["name"]
    if name.endswith("_2d"):
        return ["2d"]
    if name.endswith("_dg") or case.get("opponents"):
        return ["dg"]
    return ["dg", "2d"]


def scenario(case, config):
    ball = (case["ball"]["x_m"], case["ball"]["y_m"])
    mates = {t["id"]: (t["x_m"], t["y_m"]) for t in case["teammates"]}
    a1 = mates[1]
    regions = [o["region"] for o in config["opponents"]]
    placed = [None] * len(regions)
    for o in case.get("opponents", []):
        p = (o["x_m"], o["y_m"])
        free = [i for i in range(len(regions)) if placed[i] is None]
        holding = [i for i in free if inside(regions[i], p)]
        i = holding[0] if holding else free[0]
        placed[i] = into(regions[i], p)
    a2 = mates.get(2)
    back_m = SUPPORT_BACK_M
    while a2 is None or any(q and math.dist(a2, q) < CLEAR_M for q in placed):
        a2 = (ball[0] - back_m, clamp(ball[1] - math.copysign(SUPPORT_SIDE_M, ball[1] or 1.0),
                                       -HALF_WIDTH_M + 0.3, HALF_WIDTH_M - 0.3))
        back_m += 0.1
    for i, region in enumerate(regions):
        if placed[i] is None:
            placed[i] = waiting(region, ball, [a1, a2] + [p for p in placed if p])

    def pose(p):
        return {"x_m": round(p[0], 3), "y_m": round(p[1], 3), "theta_deg": facing(p, ball)}

    return {
        "name": case["name"],
        "notes": "case_duels.py: the situation of case " + case["name"],
        "ball": {"x_m": ball[0], "y_m": ball[1]},
        "attackers": [pose(a1), pose(a2)],
        "opponents": [pose(p) for p in placed],
    }


def first_cases(folder):
    first = {}
    with (folder / "passing_cbr_events.csv").open() as f:
        for row in csv.DictReader(f):
            d = row["detail"]
            if row["event"] == "message" and d.startswith("cbr case cycle "):
                first.setdefault((row["scenario"], row["trial"]), d.split()[4])
    per = collections.defaultdict(collections.Counter)
    for (s, _), name in first.items():
        per[s][name] += 1
    return per


def run(out, config_name, cases, trials, seed):
    config = json.loads((MODELS / "match" / f"{config_name}.json").read_text())
    folder = (out / config_name).resolve()
    folder.mkdir(parents=True, exist_ok=True)
    names = []
    for case in cases:
        if config_name not in configs_of(case):
            continue
        (folder / f"{case['name']}.json").write_text(json.dumps(scenario(case, config), indent=2))
        names.append(str(folder / f"{case['name']}.json"))
    if not names:
        return []
    config["name"] = f"{config_name}_case_duels"
    config["scenarios"] = names
    (folder / "config.json").write_text(json.dumps(config, indent=2))
    subprocess.run([str(FORESIGHT), "experiment", "passing", "--config", str(folder / "config.json"),
                    "--team", "both", "--trials", str(trials), "--seed", str(seed),
                    "--threads", "2", "--out", str(folder / "run")],
                   check=True, stdout=subprocess.DEVNULL)
    comparison = json.loads((folder / "run" / "passing_comparison.json").read_text())
    first = first_cases(folder / "run")
    rows = []
    for s in comparison["scenarios"]:
        m = s["measures"]
        top = first[str(s["scenario"])].most_common(1)
        top = f"{top[0][0]} {top[0][1]}" if top else "none"
        rows.append((config_name, s["name"], top, m["goal"], m["to_goal"], m["out"]))
    return rows


def main(out, trials=200, seed=1, only=()):
    cases = [json.loads(p.read_text()) for p in sorted((MODELS / "cases").glob("*.json"))]
    cases = [c for c in cases if "teammates" in c and (not only or c["name"] in only)]
    rows = run(out, "dg", cases, trials, seed) + run(out, "2d", cases, trials, seed)
    print("| cfg | case | first retrieved | goal cbr / reactive | to goal cbr / reactive | "
          "to goal difference [95 %] | out cbr / reactive |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for cfg, name, top, goal, to_goal, outs in rows:
        lo, hi = to_goal["difference_ci"]
        verdict = "better" if lo > 0 else "worse" if hi < 0 else "same"
        print(f"| {cfg} | {name} | {top} | {100 * goal['cbr']:.1f} / {100 * goal['reactive']:.1f} | "
              f"{100 * to_goal['cbr']:.1f} / {100 * to_goal['reactive']:.1f} | "
              f"{100 * to_goal['difference']:+.1f} [{100 * lo:+.1f}, {100 * hi:+.1f}] {verdict} | "
              f"{100 * outs['cbr']:.1f} / {100 * outs['reactive']:.1f} |")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(Path(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 200,
         int(sys.argv[3]) if len(sys.argv) > 3 else 1, tuple(sys.argv[4:]))
