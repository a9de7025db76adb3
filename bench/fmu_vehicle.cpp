// The vehicle FMU's step: one fmi2DoStep of one RK4 step (H = the internal
// step, 1 ms) of bench/runtime_vehicle.cpp's vehicle (bench_simulate's
// ASR-V-like vehicle with six 2-D gridded surfaces, 20 x 20, one per DOF),
// in a current, driven as a host drives it: the FMU binary (the build's
// hydrocoef_fmu, the bytes `hydrocoef export-fmu` embeds) dlopened, its
// resources/model.hcr written, instantiated, initialised, then per
// iteration fmi2SetReal of the six control inputs, fmi2DoStep and
// fmi2GetReal of the 22 outputs (pose, attitude, Euler angles, velocities,
// damping). Goal (issue 37): <= 1.5 us per step.
#include <benchmark/benchmark.h>
#include <dlfcn.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#define HYDROCOEF_FMI2_HOST
#include "bench/six_surface_vehicle.hpp"
#include "hydrocoef/fmi2_interface.h"
#include "src/dynamics/rigid_body.hpp"
#include "src/dynamics/vehicle_model.hpp"
#include "src/export/fmu_model_description.hpp"
#include "src/export/runtime_export.hpp"

namespace hydrocoef {
namespace {

// bench_simulate's six-surface ASR-V-like vehicle as the vehicle FMU's runtime file (fmu_model = vehicle).
std::string six_surface_runtime_file(Interpolation method) {
  return bench::six_surface_runtime_bytes(method, {{"fmu_model", "vehicle"}});
}

void logger(fmi2ComponentEnvironment, fmi2String, fmi2Status status, fmi2String category, fmi2String message, ...) {
  if (status == fmi2OK) return;
  std::va_list arguments;
  va_start(arguments, message);
  std::fprintf(stderr, "fmu [%s]: ", category);
  std::vfprintf(stderr, message, arguments);
  std::fprintf(stderr, "\n");
  va_end(arguments);
}

template <typename F>
F* resolve(void* library, const char* name) {
  void* symbol = dlsym(library, name);
  if (symbol == nullptr) throw std::runtime_error(std::string("the FMU binary has no ") + name);
  return reinterpret_cast<F*>(symbol);
}

void run_fmu_step(benchmark::State& state, Interpolation method) {
  const std::string bytes = six_surface_runtime_file(method);
  std::uint64_t hash = 0;
  for (int i = 7; i >= 0; --i)
    hash = (hash << 8) | static_cast<unsigned char>(bytes.at(24 + static_cast<std::size_t>(i)));
  const std::string guid = fmu_guid(hash);
  const auto dir = std::filesystem::temp_directory_path() / ("hydrocoef-bench-fmu-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir / "resources");
  std::ofstream(dir / "resources/model.hcr", std::ios::binary) << bytes;
  void* library = dlopen(HYDROCOEF_FMU_BINARY, RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) {
    state.SkipWithError(dlerror());
    return;
  }
  const auto instantiate = resolve<fmi2InstantiateTYPE>(library, "fmi2Instantiate");
  const auto setup = resolve<fmi2SetupExperimentTYPE>(library, "fmi2SetupExperiment");
  const auto enter = resolve<fmi2EnterInitializationModeTYPE>(library, "fmi2EnterInitializationMode");
  const auto exit = resolve<fmi2ExitInitializationModeTYPE>(library, "fmi2ExitInitializationMode");
  const auto set_real = resolve<fmi2SetRealTYPE>(library, "fmi2SetReal");
  const auto get_real = resolve<fmi2GetRealTYPE>(library, "fmi2GetReal");
  const auto do_step = resolve<fmi2DoStepTYPE>(library, "fmi2DoStep");
  const auto free_instance = resolve<fmi2FreeInstanceTYPE>(library, "fmi2FreeInstance");
  const fmi2CallbackFunctions callbacks{logger, nullptr, nullptr, nullptr, nullptr};
  const std::string uri = "file://" + (dir / "resources").string();
  fmi2Component c = instantiate("bench", fmi2CoSimulation, guid.c_str(), uri.c_str(), &callbacks, fmi2False, fmi2False);
  if (c == nullptr) {
    state.SkipWithError("fmi2Instantiate failed");
    return;
  }
  // The vehicle's value references (fmu/src/fmu_vehicle.c): inputs 0..8, outputs 9..30, parameters 31..43.
  const std::array<fmi2ValueReference, 6> tau_vr{0, 1, 2, 3, 4, 5};
  const std::array<fmi2ValueReference, 3> current_vr{6, 7, 8};
  const std::array<fmi2ValueReference, 4> parameter_vr{31, 35, 36, 37};  // step, phi0, theta0, psi0
  std::array<fmi2ValueReference, 22> outputs_vr{};
  for (std::size_t k = 0; k < outputs_vr.size(); ++k) outputs_vr[k] = static_cast<fmi2ValueReference>(9 + k);
  const double h = 1e-3;
  const std::array<double, 6> tau{0.5, 0.1, 0.0, 0.0, 0.0, 0.003};
  const std::array<double, 3> current{0.05, 0.02, 0.0};
  const std::array<double, 4> parameters{h, 0.05, 0.02, 0.3};
  std::array<double, 22> outputs{};
  if (setup(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK || enter(c) != fmi2OK ||
      set_real(c, parameter_vr.data(), parameter_vr.size(), parameters.data()) != fmi2OK ||
      set_real(c, current_vr.data(), current_vr.size(), current.data()) != fmi2OK || exit(c) != fmi2OK) {
    state.SkipWithError("the FMU's set-up failed");
    free_instance(c);
    return;
  }
  double t = 0.0;
  for (auto _ : state) {
    if (set_real(c, tau_vr.data(), tau_vr.size(), tau.data()) != fmi2OK || do_step(c, t, h, fmi2True) != fmi2OK ||
        get_real(c, outputs_vr.data(), outputs_vr.size(), outputs.data()) != fmi2OK) {
      state.SkipWithError("fmi2DoStep failed");
      break;
    }
    t += h;
    benchmark::DoNotOptimize(outputs);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["vehicle_s"] = t;
  free_instance(c);
  dlclose(library);
  std::filesystem::remove_all(dir);
}

void BM_FmuVehicleStepSixSurfacesLinear(benchmark::State& state) { run_fmu_step(state, Interpolation::Linear); }
void BM_FmuVehicleStepSixSurfacesPchip(benchmark::State& state) { run_fmu_step(state, Interpolation::Pchip); }

}  // namespace
}  // namespace hydrocoef

BENCHMARK(hydrocoef::BM_FmuVehicleStepSixSurfacesLinear);
BENCHMARK(hydrocoef::BM_FmuVehicleStepSixSurfacesPchip);
BENCHMARK_MAIN();
