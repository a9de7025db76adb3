#!/usr/bin/env bash
# The ASR-V example: the damping tables of the ASR-V spherical robot study
# (shell radius 0.15 m, ANSYS CFX, SST) imported into a run database and
# fitted with the damping laws of the paper's eq. (5) and (6).
#
#   examples/asr-v/run.sh HYDROCOEF_BINARY DATABASE
#
# Then coefficient surfaces over the surge speed and the yaw rate are built
# from the runs, queried with their gradients, and exported (JSON, a C header,
# MATLAB) into asr-v-export/ beside the database (in the current folder for a
# postgresql:// URL); the pool test is simulated,
# and with the fits' covariances drawn, given a band and an interval; the
# added mass is taken from forced-oscillation CFD runs (virtual PMM) of the
# same 0.15 m shell (examples/openfoam-sphere/pmm).
#
# What to expect (paper eq. 5 and 6, sign as in each table):
#   surge  X(u) = c + 0.01551 u + 11.0364 u|u|      (positive opposes motion)
#   yaw    N(r) = c - 0.006075 r - 0.07714 r|r|     (force on the body)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
hydrocoef=${1:?usage: run.sh HYDROCOEF_BINARY DATABASE}
db=${2:?usage: run.sh HYDROCOEF_BINARY DATABASE}
case "$db" in
*://*) out=asr-v-export ;; # a database server: the files go into the current folder
*)
  rm -f "$db"
  out=$(dirname "$db")/asr-v-export
  ;;
esac
h() { "$hydrocoef" --db "$db" "$@"; }

echo "== import: paper Table I (surge) and the yaw table, body asr-v, into $db"
# The surge table prints damping magnitudes (positive opposes motion); the yaw
# table prints the moment on the body. Each import records its convention.
h import "$here/asr-v-surge-damping.csv" --body asr-v --sign opposing --rho 998.2 --nu 1.004e-6
h import "$here/asr-v-yaw-damping.csv" --body asr-v --sign on-body --rho 998.2 --nu 1.004e-6
echo "   importing the same file again adds nothing:"
h import "$here/asr-v-yaw-damping.csv" --body asr-v --sign on-body --rho 998.2 --nu 1.004e-6

echo
echo "== runs"
h runs --body asr-v

echo
echo "== fit: surge damping, paper eq. (5)"
h fit --body asr-v --dof X --terms "1,u,u|u|"
echo
echo "== fit: surge damping without the constant term"
h fit --body asr-v --dof X --terms "u,u|u|"
echo
echo "== fit: yaw damping, paper eq. (6)"
h fit --body asr-v --dof N --terms "1,r,r|r|"

echo
echo "== stored fits"
h fits --body asr-v

echo
echo "== surfaces: surge force X(u) and yaw moment N(r), monotone cubic (PCHIP) through the runs"
# Linear continuation beyond the runs: the dynamics below may step a hair past u = 0.
h surface build asr-v-surge --body asr-v --outputs X --axes u --method pchip --extrapolate linear
h surface build asr-v-yaw --body asr-v --outputs N --axes r --method pchip --extrapolate linear
h surface list --body asr-v

echo
echo "== query: between the runs, with the local damping slope a controller linearises with"
h query asr-v-surge u=0.25 --gradient
h query asr-v-yaw r=0.15 --gradient
echo "   a point no axis of the surface names is refused:"
h query asr-v-surge v=0.1 || true

mkdir -p "$out"
echo
echo "== export into $out"
h export asr-v-yaw --format json -o "$out/asr-v-yaw.json"
h export asr-v-yaw --format c -o "$out/asr_v_yaw.h"
h export asr-v-surge --format csv -o "$out/asr-v-surge.csv"

echo
echo "== dynamics: the paper's pool test, a constant yaw torque from rest (vehicle.json: fitted laws)"
for torque in 0.0027 0.0045; do
  h equilibrium --vehicle "$here/vehicle.json" --tau "N=$torque"
done
h simulate --vehicle "$here/vehicle.json" --scenario "$here/scenario-yaw-0.0027.json" --out "$out/yaw-0.0027.csv"
echo
echo "== the same with yaw and surge damping looked up in the surfaces built above (vehicle-surfaces.json)"
h equilibrium --vehicle "$here/vehicle-surfaces.json" --tau N=0.0027
h simulate --vehicle "$here/vehicle-surfaces.json" --scenario "$here/scenario-yaw-0.0045.json" \
  --out "$out/yaw-0.0045-surfaces.csv"

echo
echo "== uncertainty: the fits' covariances drawn 2000 times (vehicle-fits.json names the stored fits)"
echo "   the steady yaw rate's 95 % interval under the paper's calibrated torque:"
h equilibrium --vehicle "$here/vehicle-fits.json" --tau N=0.0027 --samples 2000 --seed 1
echo "   the yaw-rate band of the constant-torque test (200 trajectories, 5/50/95 %):"
h simulate --vehicle "$here/vehicle-fits.json" --scenario "$here/scenario-yaw-0.0027.json" --samples 200 --seed 1 \
  --out "$out/yaw-0.0027-band.csv"

echo
echo "== added mass from a virtual PMM: OpenFOAM runs of the 0.15 m shell oscillated in surge at two amplitudes"
echo "   (examples/openfoam-sphere/pmm; potential flow: rho V / 2 = 7.056 kg, a coefficient of 0.5)"
pmm_cases="$here/../openfoam-sphere/pmm"
h pmm "$pmm_cases/surge-A0.015-T2" "$pmm_cases/surge-A0.045-T2" --body asr-v --axes=-x,y,-z --rho 998.2 \
  --nu 1.004e-6 --volume 0.014137166941154 --size 0.3
h added-mass asr-v --same sway=surge --same heave=surge --zero roll,pitch,yaw
echo "   the pool test with that added mass (vehicle-pmm.json: added_mass from_database):"
h simulate --vehicle "$here/vehicle-pmm.json" --scenario "$here/scenario-yaw-0.0027.json" --out "$out/yaw-0.0027-pmm.csv"

echo
echo "== plots (gnuplot) and a shareable report into $out"
h plot fit "asr-v:X(1,u,u|u|)" -o "$out/plots/fit-surge.png"
h plot fit "asr-v:N(1,r,r|r|)" -o "$out/plots/fit-yaw.png"
h plot surface asr-v-surge -o "$out/plots/surface-surge.png"
h plot surface asr-v-yaw -o "$out/plots/surface-yaw.png"
h plot simulation --trajectory "$out/yaw-0.0027.csv" --component r -o "$out/plots/yaw-0.0027.png"
h plot simulation --trajectory "$out/yaw-0.0027-band.csv" --component r -o "$out/plots/yaw-0.0027-band.png"
h plot steady --vehicle "$here/vehicle.json" --dof N --tau-from 0.001 --tau-to 0.006 --count 6 \
  -o "$out/plots/steady-yaw.png"
h plot steady --vehicle "$here/vehicle-fits.json" --dof N --tau-from 0.001 --tau-to 0.006 --count 6 \
  --samples 500 -o "$out/plots/steady-yaw-band.png"
h report -o "$out/report" --body asr-v --trajectory "$out/yaw-0.0027.csv" --trajectory "$out/yaw-0.0027-band.csv"
echo
echo "results: database $db; exports, trajectories and plots in $out; report: open $out/report/index.html"
