// hydrocoef: CFD results to hydrodynamic coefficient databases. The public
// C++ API, all of it (every header includes only the standard library and
// these):
//
//   hydrocoef/hydrocoef.hpp    this file: includes the others
//   hydrocoef/error.hpp        InputError, the exception for bad input, with the CLI's message
//   hydrocoef/export.hpp       HYDROCOEF_EXPORT, what the shared library exports (generated)
//   hydrocoef/version.hpp      kVersion ("0.1.0"), kVersionMajor/Minor/Patch
//   hydrocoef/database.hpp     Database: open a run database, list and select
//                              runs, import CFD results, fit damping laws,
//                              list fits and surfaces, read a surface
//   hydrocoef/integrate.hpp    integrate_surface: one surface export's forces
//                              and moments, not stored
//   hydrocoef/records.hpp      import in two steps, runs show and delete,
//                              per-level fits, refits, fits listed and
//                              evaluated, merge, copy, migrate, report
//   hydrocoef/reference.hpp    a body's reference data (body set, body show) and
//                              the runs' non-dimensional coefficients, Re and Fn
//   hydrocoef/surface.hpp      Surface: a coefficient surface evaluated at a
//                              point, with its gradient, or at many points at
//                              once on every core; tabulated for a controller;
//                              surface_build, _rebuild, _list, _show, query_surface
//   hydrocoef/exports.hpp      export_surface, export_gazebo, export_derivatives,
//                              export_forcecoeffs: a gridded surface, a body's fits, derivative
//                              models or runs (OpenFOAM forceCoeffs) written for another tool
//   hydrocoef/fmu.hpp          export_fmu: a gridded surface as an FMI 2.0 Co-Simulation FMU
//   hydrocoef/analysis.hpp     mesh studies (grid_convergence), forced oscillation (analyse_pmm,
//                              added_mass_matrix, ...), where to run CFD next (suggest_runs)
//   hydrocoef/derivatives.hpp  derivative models of several variables: fit_derivative_model,
//                              list, show (in the prime, bis or MMG form), delete, evaluate
//   hydrocoef/pmm_derivatives.hpp  pmm_derivatives: sway and yaw derivatives (Y_v, Y_vdot, ...,
//                              N_rdot) from pure sway and pure yaw forced-oscillation runs
//   hydrocoef/scaling.hpp      scale_surge_resistance: a surge resistance curve or law
//                              from one scale to another (ITTC-1957 line, form factor)
//   hydrocoef/simulation.hpp   simulate: a vehicle through a scenario, the
//                              trajectory as columns, with the Monte Carlo
//                              bands and the comparison with a measured
//                              record; equilibrium: the steady velocity
//   hydrocoef/plot.hpp         plot_fit, plot_surface, plot_history, ...:
//                              the pictures `hydrocoef plot` draws
//
// Link with the CMake target hydrocoef::hydrocoef (find_package(hydrocoef)).
// Conventions throughout: SI units; body axes after Fossen/SNAME (x forward,
// y starboard, z down); velocity u, v, w [m/s], p, q, r [rad/s]; generalized
// force X, Y, Z [N], K, M, N [N m] on the body in body axes, about the run's
// reference point (a damping force is negative along the motion).
//
// A small example:
//
//   auto db = hydrocoef::Database::open("asr-v.db", hydrocoef::OpenMode::ReadOnly);
//   hydrocoef::Surface yaw = db.surface("asr-v-yaw");        // N(r)
//   double n = yaw.evaluate({0.15})[0];                       // N m at r = 0.15 rad/s
#pragma once

#include "hydrocoef/analysis.hpp"
#include "hydrocoef/database.hpp"
#include "hydrocoef/derivatives.hpp"
#include "hydrocoef/error.hpp"
#include "hydrocoef/exports.hpp"
#include "hydrocoef/fmu.hpp"
#include "hydrocoef/integrate.hpp"
#include "hydrocoef/plot.hpp"
#include "hydrocoef/pmm_derivatives.hpp"
#include "hydrocoef/records.hpp"
#include "hydrocoef/reference.hpp"
#include "hydrocoef/scaling.hpp"
#include "hydrocoef/simulation.hpp"
#include "hydrocoef/surface.hpp"
#include "hydrocoef/version.hpp"
