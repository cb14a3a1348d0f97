#!/bin/sh
# The paper's three flow experiments at full size through the command-line tool, each
# once (they take minutes): one JSON line per run with the total time, the time per phase
# (advection, smoothing, adaptation), vertex counts, volume errors and the ratio of
# smoothing + adaptation time to bare advection time in the same run.
set -eu
cd "$(dirname "$0")/.."
tool=${SURFADAPT:-bin/surfadapt}
"$tool" enright --json --report-every 100000 | grep '^{'
"$tool" vortex --period 2 --json --report-every 100000 | grep '^{'
"$tool" vortex --period 2 --isotropic --json --report-every 100000 | grep '^{'
"$tool" vortex --period 6 --json --report-every 100000 | grep '^{'
