#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""A sphere in the vortex flow of the paper (§5.2.1, LeVeque's deformation field), moved
with a Python velocity callback (Surface.advect) and adapted every few steps, as a host
would: prints the volume every 10 steps and, when matplotlib is importable, plots the
history of every step into a PNG. With the defaults (T = 2, dt = 0.01, as `surfadapt
vortex` but on a coarser sphere) it takes a few seconds.

Run from the top of the tree after `make` (the module finds lib/ itself):
    python3 bindings/python/examples/volume_history.py [--steps 200] [--png volume_history.png]
"""
import argparse
import os
import sys

import numpy as np

# The module lies in the directory above this one, in the source tree and installed.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir))
import surfadapt  # noqa: E402


def vortex(period):
    """The velocity field u(x, t) of eqs. 13-15, reversed in time by cos(pi t / T): at t = T
    the exact solution is the starting sphere again."""
    def velocity(xyz, t):
        s, s2 = np.sin(np.pi * xyz) ** 2, np.sin(2 * np.pi * xyz)
        u = np.empty_like(xyz)
        u[:, 0] = s[:, 0] * (s2[:, 2] - s2[:, 1])
        u[:, 1] = s[:, 1] * (s2[:, 0] - s2[:, 2])
        u[:, 2] = s[:, 2] * (s2[:, 1] - s2[:, 0])
        return np.cos(np.pi * t / period) * u
    return velocity


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--steps", type=int, default=200, help="time steps to t = T (default 200)")
    ap.add_argument("--period", type=float, default=2.0, help="T of the flow (default 2)")
    ap.add_argument("--adapt-every", type=int, default=4, help="steps between adaptations (the paper: 4)")
    ap.add_argument("--png", default="volume_history.png", help="where the plot goes")
    args = ap.parse_args()

    dt = args.period / args.steps  # the run ends at t = T, back where it started
    velocity = vortex(args.period)
    xyz, tris = surfadapt.icosphere(4, radius=0.15, center=(0.5, 0.75, 0.5))
    history = []
    with surfadapt.Surface(xyz, tris) as s:
        v0 = s.measure("volume")
        print(f"{'step':>5} {'t':>7} {'vertices':>9} {'volume':>14} {'change':>10}")

        def record(step, t):
            v = s.measure("volume")
            history.append((step, t, s.nverts, v))
            if step % 10 == 0 or step == args.steps:
                print(f"{step:5d} {t:7.3f} {s.nverts:9d} {v:14.8e} {(v - v0) / v0:10.2e}")

        record(0, 0.0)
        t = 0.0
        for step in range(1, args.steps + 1):
            end = step * dt
            while t < end - 1e-12 * dt:  # the fold control may cut a step: sub-step
                t += s.advect(velocity, end - t, t)
            s.smooth(1)
            if step % args.adapt_every == 0:
                s.adapt()
            record(step, t)

    worst = max(abs(v - v0) / v0 for _, _, _, v in history)
    print(f"largest relative volume change: {worst:.2e}")
    try:
        import matplotlib
        matplotlib.use("Agg")  # no display needed: the plot goes to a file
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed: skipped the plot")
        return 0
    steps = np.array(history)
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot(steps[:, 1], (steps[:, 3] - v0) / v0, marker=".")
    ax.set_xlabel("t")
    ax.set_ylabel("relative volume change")
    ax.set_title(f"sphere in the vortex flow, T = {args.period:g}, adapted every {args.adapt_every} steps")
    fig.tight_layout()
    fig.savefig(args.png, dpi=100)
    print(f"plot written to {args.png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
