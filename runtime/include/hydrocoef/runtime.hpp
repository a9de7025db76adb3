// hydrocoef/runtime.hpp: a header-only C++ wrapper over libhydrocoef_runtime's
// C API (hydrocoef/runtime.h), for a C++ simulator or controller that loads a
// runtime file. C++20 (std::span); the library itself stays C11 and libm only:
// this header adds nothing to link.
//
//   auto model = hydrocoef::runtime::Model::open("asr-v.hcrt");
//   const std::size_t surge = model.surface_index("surge");
//   double x[1] = {0.25}, X[1];
//   model.evaluate(surge, x, X);
//
// Model owns an opened model (move-only; closed by its destructor). Opening
// throws std::runtime_error with the C library's one-line message; a call the
// C library refuses throws std::runtime_error naming the status
// (hc_runtime_status_name) and, for the vehicle functions, the library's
// message; a span of the wrong size throws std::invalid_argument before the C
// library is called. Numbers are the C library's, bit for bit: evaluate is
// hc_runtime_evaluate on the caller's buffers.
#ifndef HYDROCOEF_RUNTIME_HPP
#define HYDROCOEF_RUNTIME_HPP

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hydrocoef/runtime.h"

namespace hydrocoef::runtime {

/// The state of the vehicle functions: position (3), quaternion (4), velocity (6).
inline constexpr std::size_t kStateSize = 13;

class Model {
 public:
  /// Opens the runtime file at `path`; throws std::runtime_error with the C library's message.
  static Model open(const std::string& path) {
    hc_runtime_model* model = nullptr;
    char err[512] = "";
    const int status = hc_runtime_open(path.c_str(), &model, err, sizeof err);
    if (status != HC_RUNTIME_OK) throw std::runtime_error(err);
    return Model(model);
  }

  /// Opens a runtime file held in memory (copied).
  static Model from_memory(std::span<const std::byte> bytes) {
    hc_runtime_model* model = nullptr;
    char err[512] = "";
    const int status = hc_runtime_open_memory(bytes.data(), bytes.size(), &model, err, sizeof err);
    if (status != HC_RUNTIME_OK) throw std::runtime_error(err);
    return Model(model);
  }
  static Model from_memory(std::string_view bytes) { return from_memory(std::as_bytes(std::span(bytes))); }

  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;
  Model(Model&& other) noexcept : model_(std::exchange(other.model_, nullptr)) {}
  Model& operator=(Model&& other) noexcept {
    if (this != &other) {
      hc_runtime_close(model_);
      model_ = std::exchange(other.model_, nullptr);
    }
    return *this;
  }
  ~Model() { hc_runtime_close(model_); }

  /// The C model, for the C functions this class does not wrap (nullptr after a move).
  const hc_runtime_model* get() const noexcept { return model_; }

  std::size_t surface_count() const { return hc_runtime_surface_count(checked()); }
  /// The position of the surface named `name`; throws std::out_of_range when there is none.
  std::size_t surface_index(const std::string& name) const {
    std::size_t index = 0;
    if (hc_runtime_surface_index(checked(), name.c_str(), &index) != HC_RUNTIME_OK)
      throw std::out_of_range("no surface '" + name + "' in the runtime file");
    return index;
  }
  std::vector<std::string> surface_names() const {
    std::vector<std::string> names;
    for (std::size_t s = 0; s < surface_count(); ++s) names.push_back(text(hc_runtime_surface_name(model_, s)));
    return names;
  }
  std::string surface_name(std::size_t surface) const {
    return text(hc_runtime_surface_name(checked_surface(surface), surface));
  }
  std::string method(std::size_t surface) const {
    return text(hc_runtime_surface_method(checked_surface(surface), surface));
  }
  bool has_sigma(std::size_t surface) const {
    return hc_runtime_surface_has_sigma(checked_surface(surface), surface) != 0;
  }
  std::size_t axis_count(std::size_t surface) const { return hc_runtime_axis_count(checked_surface(surface), surface); }
  std::size_t output_count(std::size_t surface) const {
    return hc_runtime_output_count(checked_surface(surface), surface);
  }
  std::vector<std::string> axis_names(std::size_t surface) const {
    return texts(surface, axis_count(surface), hc_runtime_axis_name);
  }
  std::vector<std::string> axis_units(std::size_t surface) const {
    return texts(surface, axis_count(surface), hc_runtime_axis_unit);
  }
  std::vector<std::string> output_names(std::size_t surface) const {
    return texts(surface, output_count(surface), hc_runtime_output_name);
  }
  std::vector<std::string> output_units(std::size_t surface) const {
    return texts(surface, output_count(surface), hc_runtime_output_unit);
  }
  /// A model-level text by key (hc_runtime_metadata); empty when absent.
  std::string metadata(const std::string& key) const { return text(hc_runtime_metadata(checked(), key.c_str())); }

  /// hc_runtime_evaluate: x has axis_count entries, values output_count;
  /// gradients (output_count * axis_count) and sigma (output_count) may be
  /// empty (not computed).
  void evaluate(std::size_t surface, std::span<const double> x, std::span<double> values,
                std::span<double> gradients = {}, std::span<double> sigma = {}) const {
    const std::size_t n = axis_count(surface), n_out = output_count(surface);
    check_size("x", x.size(), n);
    check_size("values", values.size(), n_out);
    if (!gradients.empty()) check_size("gradients", gradients.size(), n * n_out);
    if (!sigma.empty()) check_size("sigma", sigma.size(), n_out);
    const int status =
        hc_runtime_evaluate(model_, surface, x.data(), values.data(), gradients.empty() ? nullptr : gradients.data(),
                            sigma.empty() ? nullptr : sigma.data());
    if (status != HC_RUNTIME_OK) {
      char err[512] = "";
      hc_runtime_check_point(model_, surface, x.data(), err, sizeof err);
      fail(status, err);
    }
  }

  bool has_vehicle() const { return hc_runtime_has_vehicle(checked()) != 0; }
  std::vector<std::string> disturbance_names() const {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < hc_runtime_vehicle_disturbance_count(checked()); ++i)
      names.push_back(text(hc_runtime_vehicle_disturbance_name(model_, i)));
    return names;
  }

  /// hc_runtime_vehicle_derivative: x and x_dot 13, tau_b 6, current_n 3 or
  /// empty (none), disturbances one per disturbance_names() entry.
  void vehicle_derivative(std::span<const double> x, std::span<const double> tau_b, std::span<const double> current_n,
                          std::span<const double> disturbances, std::span<double> x_dot) const {
    check_vehicle_inputs(x, tau_b, current_n, disturbances);
    check_size("x_dot", x_dot.size(), kStateSize);
    char err[512] = "";
    const int status = hc_runtime_vehicle_derivative(model_, x.data(), tau_b.data(), or_null(current_n),
                                                     or_null(disturbances), x_dot.data(), err, sizeof err);
    if (status != HC_RUNTIME_OK) fail(status, err);
  }

  /// hc_runtime_vehicle_step_rk4: x (13) replaced by the state dt later.
  void vehicle_step_rk4(std::span<double> x, std::span<const double> tau_b, std::span<const double> current_n,
                        std::span<const double> disturbances, double dt) const {
    check_vehicle_inputs(x, tau_b, current_n, disturbances);
    char err[512] = "";
    const int status = hc_runtime_vehicle_step_rk4(model_, x.data(), tau_b.data(), or_null(current_n),
                                                   or_null(disturbances), dt, err, sizeof err);
    if (status != HC_RUNTIME_OK) fail(status, err);
  }

 private:
  explicit Model(hc_runtime_model* model) noexcept : model_(model) {}

  const hc_runtime_model* checked() const {
    if (model_ == nullptr) throw std::logic_error("hydrocoef::runtime::Model used after a move");
    return model_;
  }
  const hc_runtime_model* checked_surface(std::size_t surface) const {
    if (surface >= surface_count())
      throw std::out_of_range("surface " + std::to_string(surface) + " of a runtime file of " +
                              std::to_string(surface_count()) + " surfaces");
    return model_;
  }
  static std::string text(const char* value) { return value == nullptr ? std::string() : std::string(value); }
  std::vector<std::string> texts(std::size_t surface, std::size_t count,
                                 const char* (*name_of)(const hc_runtime_model*, std::size_t, std::size_t)) const {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < count; ++i) out.push_back(text(name_of(model_, surface, i)));
    return out;
  }
  static void check_size(const char* what, std::size_t found, std::size_t expected) {
    if (found != expected)
      throw std::invalid_argument(std::string(what) + " has " + std::to_string(found) + " entries; expected " +
                                  std::to_string(expected));
  }
  static const double* or_null(std::span<const double> values) { return values.empty() ? nullptr : values.data(); }
  void check_vehicle_inputs(std::span<const double> x, std::span<const double> tau_b, std::span<const double> current_n,
                            std::span<const double> disturbances) const {
    checked();
    check_size("x", x.size(), kStateSize);
    check_size("tau_b", tau_b.size(), 6);
    if (!current_n.empty()) check_size("current_n", current_n.size(), 3);
    check_size("disturbances", disturbances.size(), hc_runtime_vehicle_disturbance_count(model_));
  }
  [[noreturn]] static void fail(int status, const char* message) {
    std::string what = hc_runtime_status_name(status);
    if (message != nullptr && *message != '\0') what += ": " + std::string(message);
    throw std::runtime_error(what);
  }

  hc_runtime_model* model_ = nullptr;
};

}  // namespace hydrocoef::runtime

#endif
