// Pictures of what a run database holds and of the dynamics model, as
// `hydrocoef plot` draws them: stored fits, coefficient curves over a
// disturbance, surfaces, a run's force history, a simulated trajectory and the
// steady velocity against a force. Each writes an image (PNG or SVG, drawn by
// gnuplot, which must be installed), the values drawn beside it (NAME.dat) and
// the gnuplot script (NAME.gp), so a figure can be redrawn or restyled.
//
// Units and frames as everywhere in hydrocoef: SI, body axes (x forward, y
// starboard, z down), forces on the body (a damping force is negative along
// the motion).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "hydrocoef/database.hpp"
#include "hydrocoef/error.hpp"
#include "hydrocoef/export.hpp"
#include "hydrocoef/reference.hpp"
#include "hydrocoef/simulation.hpp"

namespace hydrocoef {
inline namespace api {

/// The image a plot writes.
struct ImageOptions {
  /// FILE.png or FILE.svg (FILE.dat and FILE.gp go beside it); "" : a name
  /// made from the plot's kind and subject ("fit-asr-v_X_1_u_u_u_.png") in the working directory.
  std::string image;
  /// WIDTHxHEIGHT [pixels] ("900x600"); "" : the plot's own default (900x600; a
  /// history 900 wide and 260 per panel plus 200).
  std::string size;

  /// InputError naming --size or the image when one is bad.
  void validate() const;
};

/// The files a plot wrote and what it drew.
struct HYDROCOEF_EXPORT PlotFiles {
  std::string title;
  std::string image;
  std::string data;    ///< the values drawn
  std::string script;  ///< the gnuplot script
  std::string format;  ///< "png" or "svg"
  int width = 0;       ///< pixels
  int height = 0;
  struct Series {
    std::string panel;
    std::string title;
    std::size_t points = 0;
  };
  std::vector<Series> series;

  /// What `hydrocoef plot` prints; with json(), what `--json` prints.
  std::string text() const;
  std::string json() const;
};

/// Force against velocity of a stored fit: its runs as points, the law as a
/// curve (per-level fits NAME@LEVEL=VALUE drawn together).
HYDROCOEF_EXPORT PlotFiles plot_fit(const Database& database, const std::string& name, const ImageOptions& image = {});

/// Each coefficient of per-level fits against the disturbance they were made per level of.
struct CurvesPlotOptions {
  std::string name;  ///< base name of the per-level fits; "" : made from body, dof and terms
  std::string body, dof, terms;
  std::string by;                      ///< the disturbance, checked when given
  std::string curve = "polynomial:2";  ///< polynomial:D (least squares, degree D) or pchip
  void validate() const;
};
HYDROCOEF_EXPORT PlotFiles plot_curves(const Database& database, const CurvesPlotOptions& options,
                                       const ImageOptions& image = {});

/// A stored surface: a curve (1 axis) or a colour map (2 axes) with its runs
/// and the out-of-range regions; `output` "" : its first.
HYDROCOEF_EXPORT PlotFiles plot_surface(const Database& database, const std::string& name,
                                        const std::string& output = "", const ImageOptions& image = {});

/// One run's stored force history: the history in brief, each averaged
/// component's window, mean and standard error, spread and trend.
HYDROCOEF_EXPORT PlotFiles plot_history(const Database& database, std::int64_t run, const ImageOptions& image = {});

/// A velocity component against time from a trajectory CSV (`hydrocoef
/// simulate --out`), a measured record ("" : none) overlaid.
HYDROCOEF_EXPORT PlotFiles plot_simulation(const std::string& trajectory_csv, const std::string& experiment = "",
                                           const std::string& component = "r", const ImageOptions& image = {});

/// A non-dimensional coefficient of the runs against Re, Fn or U (`hydrocoef
/// plot coefficient`): one set of points per body, with the reference each
/// uses named in its legend; runs where either value is not defined (no rho,
/// no nu, U = 0) are left out.
struct CoefficientPlotOptions {
  std::string coefficient = "C_X";  ///< C_X, C_Y, C_Z, C_K, C_M or C_N
  std::string against = "Re";       ///< Re, Fn or U
  CoefficientOptions runs;          ///< which runs, which area (as run_coefficients)
  HYDROCOEF_EXPORT void validate() const;
};
HYDROCOEF_EXPORT PlotFiles plot_coefficient(const Database& database, const CoefficientPlotOptions& options,
                                            const ImageOptions& image = {});

/// Steady velocity against a constant force in one DOF (the equilibrium solver, attitude held).
struct SteadyPlotOptions {
  std::string vehicle;       ///< a vehicle JSON file, or the JSON text
  std::string database;      ///< where its stored fits and surfaces are read ("" : none)
  std::string dof = "N";     ///< X..N; its own velocity is drawn (N -> r)
  std::vector<double> taus;  ///< forces to solve at [N or N m]
  /// And `count` forces evenly from tau_from to tau_to (both NaN: none).
  double tau_from = std::numeric_limits<double>::quiet_NaN();
  double tau_to = std::numeric_limits<double>::quiet_NaN();
  std::size_t count = 6;
  std::string experiment_points;  ///< CSV of measured steady points, force,velocity (SI); "" : none
  /// samples > 0: the steady velocity's band over the damping's uncertainty (percentiles default 2.5, 97.5).
  SamplingOptions sampling;
  void validate() const;
};
HYDROCOEF_EXPORT PlotFiles plot_steady(const SteadyPlotOptions& options, const ImageOptions& image = {});

}  // namespace api
}  // namespace hydrocoef
