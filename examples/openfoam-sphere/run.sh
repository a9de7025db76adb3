#!/usr/bin/env bash
# Real CFD surfaces: the OpenFOAM runs of a 0.15 m sphere in data/
# (simpleFoam, k-omega SST; see data/openfoam-sphere/README.md),
# integrated from their .vtp patches and stored as runs in body axes.
#
#   examples/openfoam-sphere/run.sh HYDROCOEF_BINARY DATABASE
#
# OpenFOAM's axes: x along the free stream, z up. Body axes: x forward (into
# the stream), z down, so --axes -x,y,-z; the body moves at minus the free
# stream, which --flow states in OpenFOAM's axes. p and wallShearStress are
# kinematic (times --rho) and wallShearStress is the stress on the fluid, as
# hydrocoef assumes for those names. What to expect: X (drag on the body)
# negative and matching -Fx of case.json to ~1e-6 N; the integrate output
# shows the pressure and viscous parts and a closed surface of 4024 faces.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
hydrocoef=${1:?usage: run.sh HYDROCOEF_BINARY DATABASE}
db=${2:?usage: run.sh HYDROCOEF_BINARY DATABASE}
data="$here/../../data/openfoam-sphere/full"
rm -f "$db"

echo "== integrate one run (not stored), body axes, moments about the centre"
"$hydrocoef" integrate "$data/u0.10_v0.05/u0.10_v0.05_sphere_t1000.vtp" --rho 998.2 --axes=-x,y,-z \
  --flow 0.1,0.05,0 --body sphere

echo
echo "== import the four full-domain runs"
for case in u0.10_v0.00 u0.10_v0.05 u0.20_v0.10 u0.30_v0.00; do
  u=${case#u}; u=${u%%_*}; v=${case##*_v}
  "$hydrocoef" --db "$db" import "$data/$case/${case}_sphere_t1000.vtp" --body sphere --rho 998.2 --nu 1.004e-6 \
    --axes=-x,y,-z --flow "$u,$v,0"
done

echo
echo "== runs (forces on the body, body axes)"
"$hydrocoef" --db "$db" runs --body sphere

echo
echo "== surge drag X = c u|u| at v = 0 (least squares over the two runs there; c / (rho pi R^2 / 2) is the drag coefficient)"
"$hydrocoef" --db "$db" fit --body sphere --dof X --terms "u|u|" --where v=0 --where w=0
