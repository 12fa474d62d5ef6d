#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""Plots the speed-accuracy sweep of `meff sweep` (sweep.csv): error against cost, log-log.

Run by `meff sweep` when python3 with matplotlib is available:
    plot_sweep.py CSV PNG [--title T] [--cost wall|cpu]
One point per engine and setting: colour for the engine (meff in Box2D's order, by colour and by
soft step; Box2D 2.4.1), marker for the
group of settings the point belongs to. Each engine's Pareto front (the settings more accurate,
by over 1%, than every cheaper setting of that engine) is drawn as a line and its points
labelled; the default setting (8 velocity and 3 position iterations, 60 Hz, block solver and
warm starting on) is ringed.
Writes PNG (format png whatever its name ends with). Exit status 0 on success.
"""
import argparse
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)
from matplotlib.lines import Line2D  # noqa: E402

ENGINES = [("meff", "meff, Box2D's order", "tab:blue"), ("meff_colour", "meff by colour", "tab:green"),
           ("meff_soft_step", "meff soft step", "tab:red"), ("box2d", "Box2D 2.4.1", "tab:orange")]
GROUPS = [
    ("iterations_dt", "velocity iterations × dt (3 position)", "o"),
    ("position_dt", "position iterations × dt (8 velocity)", "s"),
    ("block_off", "block solver off × dt (8/3)", "^"),
    ("warm_off", "warm starting off × dt (8/3)", "D"),
    ("colour", "by colour × dt (8/3)", "P"),
    ("soft_step", "soft step: substeps × dt", "v"),
    ("soft_stiffness", "soft step: joint stiffness (60 Hz, 4 substeps)", "X"),
]


def read_rows(path, cost_column):
    with open(path, newline="") as stream:
        rows = list(csv.DictReader(stream))
    points = []
    for row in rows:
        try:
            cost = float(row[cost_column])
            error = float(row["error_m"])
        except ValueError:
            continue
        if not (math.isfinite(cost) and math.isfinite(error)) or row["status"] != "ok":
            continue
        points.append({
            "engine": row["engine"],
            "group": row["group"],
            "cost": cost,
            "error": error,
            "v": int(row["velocity_iterations"]),
            "p": int(row["position_iterations"]),
            "hz": int(row["hz"]),
            "block": row["block_solver"] == "1",
            "warm": row["warm_starting"] == "1",
            "kind": row["error_kind"],
            # older sweep.csv files have no soft-step columns
            "substeps": int(row.get("substeps") or 0),
            "joint_hz": float(row.get("joint_hertz") or 0),
        })
    return points


# A point must beat every cheaper one's error by this fraction to be on the front (as in
# sweep_command.cpp): errors that differ only in round-off would otherwise all be on it.
FRONT_MARGIN = 0.01


def pareto_front(points):
    """The points whose error every cheaper point's exceeds by FRONT_MARGIN, cheapest first."""
    front = []
    best = math.inf
    for point in sorted(points, key=lambda p: (p["cost"], p["error"])):
        if point["error"] < (1 - FRONT_MARGIN) * best:
            front.append(point)
            best = point["error"]
    return front


def label(point):
    if point["engine"] == "meff_soft_step":
        return f"{point['substeps']}x {point['hz']}Hz {point['joint_hz']:g}Hz joints"
    text = f"{point['v']}/{point['p']} {point['hz']}Hz"
    if not point["block"]:
        text += " noblock"
    if not point["warm"]:
        text += " nowarm"
    return text


def is_default(point):
    if point["engine"] == "meff_soft_step":
        return (point["hz"], point["substeps"], point["joint_hz"]) == (60, 4, 72)
    return (point["v"], point["p"], point["hz"], point["block"], point["warm"]) == (
        8, 3, 60, True, True)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="")
    parser.add_argument("--cost", choices=["wall", "cpu"], default="wall",
                        help="x axis: wall time (ms_per_sim_s) or CPU time (cpu_ms_per_sim_s)")
    args = parser.parse_args()

    points = read_rows(args.csv, "ms_per_sim_s" if args.cost == "wall" else "cpu_ms_per_sim_s")
    floor = 1e-9  # log axes: an exact zero is drawn at the floor
    for point in points:
        point["error"] = max(point["error"], floor)
    figure, axis = plt.subplots(figsize=(10, 7))
    # Label offsets per engine, so that where the engines' fronts coincide (meff follows Box2D
    # step for step, so their errors are often equal) the labels do not overprint.
    offsets = {"meff": (5, 4), "box2d": (5, -10), "meff_colour": (5, 12), "meff_soft_step": (5, 4)}
    for engine, engine_label, colour in ENGINES:
        mine = [p for p in points if p["engine"] == engine]
        for group, _, marker in GROUPS:
            chosen = [p for p in mine if p["group"] == group]
            if chosen:
                axis.scatter([p["cost"] for p in chosen], [p["error"] for p in chosen],
                             marker=marker, s=28, color=colour, alpha=0.55)
        front = pareto_front(mine)
        if front:
            axis.plot([p["cost"] for p in front], [p["error"] for p in front], color=colour,
                      linewidth=1.8, drawstyle="steps-post")
            axis.scatter([p["cost"] for p in front], [p["error"] for p in front], s=40,
                         facecolors=colour, edgecolors="black", linewidths=0.6, zorder=3)
            for p in front:
                axis.annotate(label(p), (p["cost"], p["error"]), textcoords="offset points",
                              xytext=offsets.get(engine, (5, 4)), fontsize=7, color=colour)
        for p in mine:
            if is_default(p):
                axis.scatter([p["cost"]], [p["error"]], s=170, facecolors="none",
                             edgecolors=colour, linewidths=1.8, zorder=4)
    handles = [Line2D([], [], color=colour, linewidth=1.8, marker="o", markeredgecolor="black",
                      label=f"{engine_label} (line: its Pareto front)")
               for _, engine_label, colour in ENGINES]
    handles += [Line2D([], [], linestyle="none", marker=marker, color="gray", label=group_label)
                for _, group_label, marker in GROUPS]
    handles.append(Line2D([], [], linestyle="none", marker="o", markersize=12,
                          markerfacecolor="none", markeredgecolor="gray",
                          label="defaults: 8/3 iterations, 60 Hz; soft step 4 substeps"))
    axis.set_xscale("log")
    axis.set_yscale("log")
    axis.set_xlabel(f"cost: {'wall' if args.cost == 'wall' else 'CPU'} time per simulated "
                    "second (ms), median of the timed runs")
    kind = points[0]["kind"] if points else ""
    what = ("against the exact answer" if kind.startswith("analytic")
            else "against a converged reference run")
    axis.set_ylabel(f"error (m), {what}")
    axis.grid(True, which="major", alpha=0.3)
    axis.grid(True, which="minor", alpha=0.1)
    axis.legend(handles=handles, loc="best", fontsize="small")
    axis.set_title(args.title + "\nlabels: velocity/position iterations, rate")
    figure.tight_layout()
    figure.savefig(args.png, format="png", dpi=100)
    return 0


if __name__ == "__main__":
    sys.exit(main())
