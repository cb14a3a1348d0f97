# SPDX-License-Identifier: BSD-3-Clause
"""Two drops driven into each other with topology change on, for the README's picture
(doc/render.sh): writes OUT_DIR/two_drops.obj with three moments side by side along x,
before the merge, at the first call that merged them, and after a few more sfa_adapt calls.
Run from the top of the tree after `make`: PYTHONPATH=bindings/python python3 doc/two_drops.py OUT_DIR"""
import os
import sys

import numpy as np
import surfadapt


def drops():
    """Two spheres of radius 0.2 whose centres are 0.46 apart on the x axis (a gap of 0.06)."""
    a, ta = surfadapt.icosphere(4, radius=0.2, center=(-0.23, 0.0, 0.0))
    b, tb = surfadapt.icosphere(4, radius=0.2, center=(0.23, 0.0, 0.0))
    return np.vstack([a, b]), np.vstack([ta, tb + len(a)])


def main(out_dir):
    frames = []
    with surfadapt.Surface(*drops()) as s:
        s.set_param("edge_length", 0.03)
        s.set_param("topology_change", 1)
        s.adapt()
        frames.append(s.mesh())
        for step in range(200):
            xyz, _ = s.mesh()
            toward = np.zeros_like(xyz)
            toward[:, 0] = np.where(xyz[:, 0] < 0, 0.25, -0.25)
            s.move(toward, 0.01)
            s.adapt()
            if s.measure("merges") > 0:
                break
        else:
            raise SystemExit("the drops did not merge in 200 steps")
        frames.append(s.mesh())
        for _ in range(6):
            s.adapt()
        frames.append(s.mesh())
        print(f"merged after {step + 1} steps; {s.component_count} component(s)")
    with open(os.path.join(out_dir, "two_drops.obj"), "w", encoding="ascii") as f:
        base = 1
        for k, (xyz, tris) in enumerate(frames):
            for p in xyz:
                f.write(f"v {p[0] + 1.1 * k:.17g} {p[1]:.17g} {p[2]:.17g}\n")
            for t in tris:
                f.write(f"f {t[0] + base} {t[1] + base} {t[2] + base}\n")
            base += len(xyz)


if __name__ == "__main__":
    main(sys.argv[1])
