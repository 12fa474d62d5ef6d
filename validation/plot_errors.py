#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""Plots the per-frame errors of `meff validate` (divergence.csv) against their tolerances.

Run by `meff validate --report DIR` when python3 with matplotlib is available:
    plot_errors.py CSV PNG --title T --tolerances POS ANGLE VEL IMPULSE
                   [--divergence FRAME] [--horizon FRAME]
Writes PNG (format png whatever its name ends with). Exit status 0 on success.
"""
import argparse
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)

# (csv column, label, unit, index into --tolerances)
SERIES = [
    ("position_error", "position", "m", 0),
    ("angle_error", "angle", "rad", 1),
    ("velocity_error", "velocity", "m/s, rad/s", 2),
    ("contact_impulse_error", "contact impulse", "N·s", 3),
    ("joint_impulse_error", "joint impulse", "N·s", 3),
]


def read_columns(path):
    with open(path, newline="") as stream:
        rows = list(csv.DictReader(stream))
    frames = [int(row["frame"]) for row in rows]
    columns = {}
    for name, _, _, _ in SERIES:
        values = []
        for row in rows:
            try:
                values.append(float(row[name]))
            except ValueError:
                values.append(math.nan)
        columns[name] = values
    return frames, columns


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="")
    parser.add_argument("--tolerances", type=float, nargs=4, required=True)
    parser.add_argument("--divergence", type=int)
    parser.add_argument("--horizon", type=int)
    args = parser.parse_args()

    frames, columns = read_columns(args.csv)
    figure, axes = plt.subplots(len(SERIES), 1, sharex=True, figsize=(9, 11))
    floor = 1e-12  # log axes: an exact zero is drawn at the floor
    for axis, (name, label, unit, tolerance_index) in zip(axes, SERIES):
        values = [max(v, floor) if not math.isnan(v) else math.nan for v in columns[name]]
        axis.semilogy(frames, values, linewidth=1.0, label=f"|meff − Box2D| ({unit})")
        tolerance = args.tolerances[tolerance_index]
        axis.axhline(tolerance, color="tab:red", linestyle="--", linewidth=1.0,
                     label=f"tolerance {tolerance:g}"
                     + (" (or relative)" if "impulse" in name else ""))
        if args.divergence is not None:
            axis.axvline(args.divergence, color="tab:orange", linewidth=1.0,
                         label=f"divergence (frame {args.divergence})")
        if args.horizon:
            axis.axvline(args.horizon, color="tab:gray", linestyle=":", linewidth=1.0,
                         label=f"horizon (frame {args.horizon})")
        if all(v == 0 for v in columns[name]):
            axis.text(0.5, 0.5, "identical to Box2D at every frame", transform=axis.transAxes,
                      ha="center", va="center")
        axis.set_ylabel(label)
        axis.set_ylim(bottom=floor)
        axis.grid(True, which="major", alpha=0.3)
        axis.legend(loc="upper left", fontsize="small")
    axes[-1].set_xlabel("frame")
    figure.suptitle(args.title)
    figure.tight_layout()
    figure.savefig(args.png, format="png", dpi=100)
    return 0


if __name__ == "__main__":
    sys.exit(main())
