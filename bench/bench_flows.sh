#!/bin/sh
# The paper's three flow experiments at full size through the command-line tool, each
# once (they take minutes): one JSON line per run with the total time, the time per call
# (advection, sfa_smooth, sfa_adapt) and per phase inside them (analysis, smoothing,
# flipping, splitting and contraction), vertex counts, volume errors, the largest normal
# turn and crossings, and the ratio of smoothing + adaptation time to bare advection time
# in the same run.
set -eu
cd "$(dirname "$0")/.."
tool=${SURFADAPT:-bin/surfadapt}
"$tool" enright --json --report-every 100000 | grep '^{'
"$tool" vortex --period 2 --json --report-every 100000 | grep '^{'
"$tool" vortex --period 2 --isotropic --json --report-every 100000 | grep '^{'
"$tool" vortex --period 6 --json --report-every 100000 | grep '^{'
