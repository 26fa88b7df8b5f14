"""Worked example of the Python module: calibrate the NAO's kicks from physics, then
plot the launch speeds of new physics trials of each kick (another seed) against the fitted
normal: the fit should predict them.

    PYTHONPATH=build/python python3 python/examples/calibrate_and_plot.py [OUT.png] [TRIALS]

Writes OUT.png (default: launch_speeds.png) and prints the fitted v0 and sigma_v per kick.
"""
import math
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed; set MPLBACKEND to override in a notebook
import matplotlib.pyplot as plt
import numpy as np

import foresight


def main(out="launch_speeds.png", trials=200):
    # 1. Calibrate every kick of the NAO: the report's calibration.json as a dict.
    report = foresight.calibrate("nao", trials=trials, seed=1)
    fitted = {k["name"]: k for k in report["kicks"]}

    # 2. The same physics trials, one kick at a time, as NumPy arrays.
    situation = foresight.models_dir() + "/calibration/nao.json"
    figure, axes = plt.subplots(1, len(fitted), figsize=(4 * len(fitted), 3.2))
    for axis, (name, kick) in zip(np.atleast_1d(axes), fitted.items()):
        trials_of_kick = foresight.simulate(situation, name, trials=trials, seed=2)
        speeds = trials_of_kick["launch_speed_mps"][trials_of_kick["touched"]]
        v0, sigma = kick["speed"]["mean_mps"], kick["speed"]["sd_mps"]
        axis.hist(speeds, bins=20, density=True, color="#9ecae1", label="physics trials")
        xs = np.linspace(speeds.min(), speeds.max(), 200)
        axis.plot(xs, np.exp(-0.5 * ((xs - v0) / sigma) ** 2) / (sigma * math.sqrt(2 * math.pi)),
                  color="#08519c", label=f"fit v0={v0:.3f}, sd={sigma:.3f}")
        axis.set_title(name)
        axis.set_xlabel("launch speed (m/s)")
        axis.legend(fontsize=7)
        print(f"{name}: v0 {v0:.4f} m/s, sigma_v {sigma:.4f} m/s, {speeds.size} touched trials")
    figure.tight_layout()
    figure.savefig(out, dpi=100)
    print(f"figure: {out}")
    return report


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "launch_speeds.png",
         int(sys.argv[2]) if len(sys.argv) > 2 else 200)
