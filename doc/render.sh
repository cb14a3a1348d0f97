#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Renders the README's pictures into doc/images: the machined part as generated and as
# remeshed with its ridges, a ridge band close up, the Enright sheet at t = 1.5 and t = 3,
# and two drops merging. Needs `make`, Debian's paraview (pvbatch) and xvfb (xvfb-run),
# and python3-numpy for the drops (the Python binding). Not part of `make check`: it takes
# a few minutes, mostly the Enright run.
set -eu
cd "$(dirname "$0")/.."
work=build/render
mkdir -p "$work" doc/images
for tool in pvbatch xvfb-run; do
  command -v "$tool" >/dev/null || { echo "render.sh: needs $tool (apt-get install paraview xvfb)" >&2; exit 1; }
done
[ -x bin/surfadapt ] || { echo "render.sh: run make first" >&2; exit 1; }

bin/surfadapt demo --out "$work/demo" --steps 1 >/dev/null
bin/surfadapt enright --checkpoints "$work/enright" --report-every 1000 >/dev/null
PYTHONPATH=bindings/python /usr/bin/python3 doc/two_drops.py "$work"
xvfb-run -a pvbatch doc/render.py "$work" doc/images
