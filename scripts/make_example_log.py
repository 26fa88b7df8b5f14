#!/usr/bin/env python3
"""Writes models/logs/nao_kicks_example.csv: a kick log as a team's robot would record it, made
from physics trials of the shipped NAO (`foresight simulate` in the calibration situation).

Every row is one physics trial whose ball left the foot, rolled freely and came to rest without
touching anything (trials that missed, fell or hit something are left out, as a team leaves out
kicks it could not measure). The robot's pose is the one it believes (the situation's; the
placement error physics drew is unknown to the robot), the ball where it lay, the rest position
where physics stopped it. Every third row also carries the launch (speed and direction in the
robot frame), as from a ball tracker that saw the first metres: those rows let `calibrate` fit
the rolling deceleration. The numbers are rounded as a log would hold them (mm, 0.1 deg,
0.01 m/s); there is no measurement error beyond that rounding (a perfect tracker: assumption).

Usage: scripts/make_example_log.py FORESIGHT_BINARY MODELS_DIR TRIALS_PER_KICK SEED
"""
import json
import math
import subprocess
import sys


def main():
    binary, models, trials, seed = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    situation_file = f"{models}/calibration/nao.json"
    with open(situation_file) as f:
        situation = json.load(f)
    robot = situation["robot"]
    theta = math.radians(robot["theta_deg"])
    bx, by = situation["ball"]["x_m"], situation["ball"]["y_m"]  # in the robot frame
    ball_x = robot["x_m"] + math.cos(theta) * bx - math.sin(theta) * by
    ball_y = robot["y_m"] + math.sin(theta) * bx + math.cos(theta) * by
    rows = ["kick,robot_x_m,robot_y_m,robot_theta_deg,ball_x_m,ball_y_m,"
            "launch_speed_mps,launch_direction_deg,rest_x_m,rest_y_m"]
    version = ""
    for kick in ["forward", "side_kick_left", "side_kick_right"]:
        out = subprocess.run([binary, "--models", models, "simulate", "--situation",
                              situation_file, "--kick", kick, "--trials", str(trials), "--seed",
                              str(seed), "--json"], check=True, capture_output=True, text=True)
        run = json.loads(out.stdout)
        version = run["foresight_version"]
        kept = 0
        for t in run["trials_detail"]:
            if not (t["launched"] and t["settled"]) or t["fell"] or t["first_contact"] != "none":
                continue
            launch = ","
            if kept % 3 == 0:
                launch = f"{t['launch_speed_mps']:.2f},{t['launch_direction_deg']:.1f}"
            rows.append(f"{kick},{robot['x_m']:.3f},{robot['y_m']:.3f},{robot['theta_deg']:.1f},"
                        f"{ball_x:.3f},{ball_y:.3f},{launch},"
                        f"{t['rest_m'][0]:.3f},{t['rest_m'][1]:.3f}")
            kept += 1
        print(f"{kick}: {kept} of {trials} trials kept", file=sys.stderr)
    print(f"foresight {version}, seed {seed}, {trials} trials per kick", file=sys.stderr)
    sys.stdout.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
