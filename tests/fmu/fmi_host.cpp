// The project's FMI 2.0 Co-Simulation host (fmi_host.hpp).
#include "tests/fmu/fmi_host.hpp"

#include <dlfcn.h>

#include <array>
#include <cctype>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <type_traits>

#include "src/core/xml_reference.hpp"

namespace hydrocoef::test {
namespace {

// ---- zip -------------------------------------------------------------------

std::uint32_t crc32_of(const std::string& bytes) {
  static const auto table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xedb88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  std::uint32_t crc = 0xffffffffu;
  for (const unsigned char byte : bytes) crc = table[(crc ^ byte) & 0xffu] ^ (crc >> 8);
  return crc ^ 0xffffffffu;
}

std::uint32_t le(const std::string& bytes, std::size_t at, int width, const char* what) {
  if (at > bytes.size() || bytes.size() - at < static_cast<std::size_t>(width))
    throw std::runtime_error(std::string("zip: ") + what + " at byte " + std::to_string(at) +
                             " runs past the archive's end (" + std::to_string(bytes.size()) + " bytes)");
  std::uint32_t value = 0;
  for (int i = width - 1; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
  return value;
}

void check_entry_name(const std::string& name) {
  bool bad = name.empty() || name.front() == '/' || name.find('\\') != std::string::npos ||
             name.find('\0') != std::string::npos;
  std::size_t at = 0;
  while (!bad && at <= name.size()) {
    const auto slash = name.find('/', at);
    const std::string part = name.substr(at, slash == std::string::npos ? std::string::npos : slash - at);
    bad = part == ".." || (part.empty() && slash != std::string::npos);
    at = slash == std::string::npos ? name.size() + 1 : slash + 1;
  }
  if (bad) throw std::runtime_error("zip: entry name '" + name + "' is not a safe relative path");
}

// ---- XML -------------------------------------------------------------------

class XmlReader {
 public:
  explicit XmlReader(const std::string& text) : s_(text) {}

  XmlElement document() {
    skip_misc();
    if (!starts("<")) fail("expected the root element");
    XmlElement root = element();
    skip_misc();
    if (at_ != s_.size()) fail("content after the root element");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("XML: " + what + " at byte " + std::to_string(at_));
  }
  bool starts(const char* text) const { return s_.compare(at_, std::strlen(text), text) == 0; }
  void skip_space() {
    while (at_ < s_.size() && (s_[at_] == ' ' || s_[at_] == '\t' || s_[at_] == '\n' || s_[at_] == '\r')) ++at_;
  }
  void skip_until(const char* end) {
    const auto found = s_.find(end, at_);
    if (found == std::string::npos) fail(std::string("unterminated construct, expected '") + end + "'");
    at_ = found + std::strlen(end);
  }
  void skip_misc() {
    for (;;) {
      skip_space();
      if (starts("<?")) {
        skip_until("?>");
      } else if (starts("<!--")) {
        at_ += 4;
        const auto found = s_.find("--", at_);
        if (found == std::string::npos || s_.compare(found, 3, "-->") != 0) fail("'--' inside a comment");
        at_ = found + 3;
      } else if (starts("<!")) {
        fail("a DTD or CDATA section (not read by this host)");
      } else {
        return;
      }
    }
  }
  static bool name_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':' || c == '-' || c == '.' ||
           static_cast<unsigned char>(c) >= 0x80;
  }
  std::string name() {
    const std::size_t begin = at_;
    if (at_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[at_])) || s_[at_] == '-' || s_[at_] == '.'))
      fail("a name starting with a digit, '-' or '.'");
    while (at_ < s_.size() && name_char(s_[at_])) ++at_;
    if (at_ == begin) fail("expected a name");
    return s_.substr(begin, at_ - begin);
  }
  // Text up to `end` (a quote, or '<' for character data), entities decoded.
  std::string text_until(char end) {
    std::string out;
    while (at_ < s_.size() && s_[at_] != end) {
      const char c = s_[at_];
      if (c == '<') fail("'<' inside an attribute value");
      if (c != '&') {
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r')
          fail("a control character XML 1.0 cannot hold");
        out += c;
        ++at_;
        continue;
      }
      const auto semicolon = s_.find(';', at_);
      if (semicolon == std::string::npos || semicolon - at_ > 12) fail("an unterminated entity");
      const std::string entity = s_.substr(at_ + 1, semicolon - at_ - 1);
      if (const char* wrong = append_xml_reference(entity, out)) fail(std::string(wrong) + " &" + entity + ";");
      at_ = semicolon + 1;
    }
    return out;
  }
  XmlElement element() {
    ++at_;  // '<'
    XmlElement out;
    out.name = name();
    for (;;) {
      const std::size_t before = at_;
      skip_space();
      if (starts("/>")) {
        at_ += 2;
        return out;
      }
      if (starts(">")) {
        ++at_;
        break;
      }
      if (at_ == before) fail("expected whitespace before an attribute");
      const std::string attribute = name();
      skip_space();
      if (!starts("=")) fail("expected '=' after attribute " + attribute);
      ++at_;
      skip_space();
      if (at_ >= s_.size() || (s_[at_] != '"' && s_[at_] != '\'')) fail("expected a quoted attribute value");
      const char quote = s_[at_++];
      std::string value = text_until(quote);
      if (at_ >= s_.size()) fail("an unterminated attribute value");
      ++at_;
      if (!out.attributes.emplace(attribute, std::move(value)).second) fail("duplicate attribute " + attribute);
    }
    for (;;) {
      text_until('<');
      if (at_ >= s_.size()) fail("element <" + out.name + "> is not closed");
      if (starts("</")) {
        at_ += 2;
        const std::string closing = name();
        skip_space();
        if (!starts(">")) fail("expected '>' closing </" + closing);
        ++at_;
        if (closing != out.name) fail("</" + closing + "> closes <" + out.name + ">");
        return out;
      }
      if (starts("<!--") || starts("<?")) {
        skip_misc();
        continue;
      }
      if (starts("<!")) fail("CDATA or a declaration inside an element (not read by this host)");
      out.children.push_back(element());
    }
  }

  const std::string& s_;
  std::size_t at_ = 0;
};

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

}  // namespace

std::map<std::string, std::string> unzip_stored(const std::string& bytes) {
  // The end of central directory record: the last signature within the
  // last 22 + 65535 bytes whose comment length reaches the end exactly.
  if (bytes.size() < 22) throw std::runtime_error("zip: " + std::to_string(bytes.size()) + " bytes, too short");
  std::size_t end = std::string::npos;
  const std::size_t lowest = bytes.size() > 22 + 65535 ? bytes.size() - 22 - 65535 : 0;
  for (std::size_t at = bytes.size() - 22 + 1; at-- > lowest;) {
    if (le(bytes, at, 4, "signature") == 0x06054b50u && at + 22 + le(bytes, at + 20, 2, "comment") == bytes.size()) {
      end = at;
      break;
    }
  }
  if (end == std::string::npos) throw std::runtime_error("zip: no end of central directory record");
  const std::uint32_t count = le(bytes, end + 10, 2, "entry count");
  if (le(bytes, end + 4, 2, "disk") != 0 || le(bytes, end + 6, 2, "disk") != 0 ||
      le(bytes, end + 8, 2, "entries on disk") != count)
    throw std::runtime_error("zip: a multi-disk archive");
  const std::uint32_t directory_size = le(bytes, end + 12, 4, "directory size");
  const std::uint32_t directory_offset = le(bytes, end + 16, 4, "directory offset");
  if (directory_offset > end || end - directory_offset != directory_size)
    throw std::runtime_error("zip: the central directory (offset " + std::to_string(directory_offset) + ", size " +
                             std::to_string(directory_size) + ") does not end where its end record starts (" +
                             std::to_string(end) + ")");
  std::map<std::string, std::string> files;
  std::size_t at = directory_offset;
  for (std::uint32_t i = 0; i < count; ++i) {
    if (le(bytes, at, 4, "central directory signature") != 0x02014b50u)
      throw std::runtime_error("zip: central directory entry " + std::to_string(i) + " has no signature");
    const std::uint32_t flags = le(bytes, at + 8, 2, "flags"), method = le(bytes, at + 10, 2, "method");
    const std::uint32_t crc = le(bytes, at + 16, 4, "crc"), compressed = le(bytes, at + 20, 4, "size"),
                        size = le(bytes, at + 24, 4, "size");
    const std::uint32_t name_length = le(bytes, at + 28, 2, "name length"),
                        extra_length = le(bytes, at + 30, 2, "extra length"),
                        comment_length = le(bytes, at + 32, 2, "comment length");
    const std::uint32_t local = le(bytes, at + 42, 4, "local header offset");
    if (at + 46 + name_length > end) throw std::runtime_error("zip: entry " + std::to_string(i) + "'s name overruns");
    const std::string name = bytes.substr(at + 46, name_length);
    check_entry_name(name);
    if (flags & 0x0009u) throw std::runtime_error("zip: entry '" + name + "' is encrypted or has a data descriptor");
    if (method != 0 || compressed != size)
      throw std::runtime_error("zip: entry '" + name + "' is compressed (method " + std::to_string(method) +
                               "); this host reads stored entries only");
    if (le(bytes, local, 4, "local header signature") != 0x04034b50u)
      throw std::runtime_error("zip: entry '" + name + "' has no local header at " + std::to_string(local));
    const std::uint32_t local_name = le(bytes, local + 26, 2, "local name length"),
                        local_extra = le(bytes, local + 28, 2, "local extra length");
    if (local_name != name_length || bytes.compare(local + 30, name_length, name) != 0 ||
        le(bytes, local + 8, 2, "local method") != 0 || le(bytes, local + 14, 4, "local crc") != crc ||
        le(bytes, local + 18, 4, "local size") != compressed || le(bytes, local + 22, 4, "local size") != size)
      throw std::runtime_error("zip: entry '" + name + "''s local header disagrees with the central directory");
    const std::size_t data = static_cast<std::size_t>(local) + 30 + local_name + local_extra;
    if (data > directory_offset || directory_offset - data < size)
      throw std::runtime_error("zip: entry '" + name + "''s data overruns the central directory");
    std::string content = bytes.substr(data, size);
    if (crc32_of(content) != crc) throw std::runtime_error("zip: entry '" + name + "' fails its CRC-32");
    if (!files.emplace(name, std::move(content)).second)
      throw std::runtime_error("zip: entry '" + name + "' appears twice");
    at += 46 + name_length + extra_length + comment_length;
  }
  if (at != end) throw std::runtime_error("zip: the central directory's entries do not fill it");
  return files;
}

const std::string& XmlElement::at(const std::string& attribute) const {
  const auto found = attributes.find(attribute);
  if (found == attributes.end()) throw std::runtime_error("XML: <" + name + "> has no attribute " + attribute);
  return found->second;
}

std::vector<const XmlElement*> XmlElement::all(const std::string& child) const {
  std::vector<const XmlElement*> out;
  for (const auto& c : children)
    if (c.name == child) out.push_back(&c);
  return out;
}

XmlElement parse_xml(const std::string& text) { return XmlReader(text).document(); }

ModelDescription read_model_description(const std::string& xml) {
  const XmlElement root = parse_xml(xml);
  if (root.name != "fmiModelDescription") throw std::runtime_error("the root is <" + root.name + ">");
  ModelDescription out;
  out.fmi_version = root.at("fmiVersion");
  out.model_name = root.at("modelName");
  out.guid = root.at("guid");
  const auto cs = root.all("CoSimulation");
  if (cs.size() != 1) throw std::runtime_error("expected one <CoSimulation>");
  out.co_simulation = cs.front()->attributes;
  out.model_identifier = cs.front()->at("modelIdentifier");
  for (const auto* units : root.all("UnitDefinitions"))
    for (const auto* unit : units->all("Unit")) out.units.push_back(unit->at("name"));
  const auto variables = root.all("ModelVariables");
  if (variables.size() != 1) throw std::runtime_error("expected one <ModelVariables>");
  for (const auto* v : variables.front()->all("ScalarVariable")) {
    FmiVariable variable;
    variable.name = v->at("name");
    variable.value_reference = static_cast<fmi2ValueReference>(std::stoul(v->at("valueReference")));
    variable.causality = v->attributes.count("causality") ? v->at("causality") : "local";
    variable.variability = v->attributes.count("variability") ? v->at("variability") : "continuous";
    if (v->attributes.count("description")) variable.description = v->at("description");
    const auto reals = v->all("Real");
    if (reals.size() != 1) throw std::runtime_error("variable " + variable.name + " is not one Real");
    if (reals.front()->attributes.count("unit")) variable.unit = reals.front()->at("unit");
    if (reals.front()->attributes.count("start")) variable.start = std::stod(reals.front()->at("start"));
    variable.index = out.variables.size() + 1;
    out.variables.push_back(variable);
  }
  for (const auto* structure : root.all("ModelStructure"))
    for (const auto* outputs : structure->all("Outputs"))
      for (const auto* unknown : outputs->all("Unknown")) {
        std::vector<std::size_t> dependencies;
        std::istringstream list(unknown->attributes.count("dependencies") ? unknown->at("dependencies") : "");
        for (std::size_t d; list >> d;) dependencies.push_back(d);
        out.outputs[std::stoul(unknown->at("index"))] = dependencies;
      }
  return out;
}

// ---- the host --------------------------------------------------------------

enum FmiHost::State : unsigned {
  kStartAndEnd = 1u << 0,
  kInstantiated = 1u << 1,
  kInitialization = 1u << 2,
  kStepComplete = 1u << 3,
  kStepInProgress = 1u << 4,
  kStepFailed = 1u << 5,
  kStepCanceled = 1u << 6,
  kTerminated = 1u << 7,
  kError = 1u << 8,
  kFatal = 1u << 9,
};

FmiHost::FmiHost(const std::filesystem::path& fmu, const std::filesystem::path& dir)
    : dir_(dir), callbacks_{&FmiHost::logger, std::calloc, std::free, nullptr, this}, state_(kStartAndEnd) {
  const auto files = unzip_stored(read_file(fmu));
  for (const auto& [name, content] : files) {
    const std::filesystem::path path = dir_ / name;
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << content;
  }
  const auto description = files.find("modelDescription.xml");
  if (description == files.end()) throw std::runtime_error("the FMU has no modelDescription.xml");
  model_ = read_model_description(description->second);
  if (model_.fmi_version != "2.0") throw std::runtime_error("fmiVersion " + model_.fmi_version + ", expected 2.0");
  const std::filesystem::path binary = dir_ / "binaries" / "linux64" / (model_.model_identifier + ".so");
  if (!files.count("binaries/linux64/" + model_.model_identifier + ".so"))
    throw std::runtime_error("the FMU has no binaries/linux64/" + model_.model_identifier + ".so");
  library_ = dlopen(binary.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (library_ == nullptr) throw std::runtime_error(std::string("dlopen: ") + dlerror());
  const auto resolve = [this](auto& pointer, const char* name) {
    pointer = reinterpret_cast<std::remove_reference_t<decltype(pointer)>>(dlsym(library_, name));
    if (pointer == nullptr) throw std::runtime_error(std::string("the FMU binary does not export ") + name);
  };
  Fmi2Functions& f = functions_;
  resolve(f.GetTypesPlatform, "fmi2GetTypesPlatform");
  resolve(f.GetVersion, "fmi2GetVersion");
  resolve(f.SetDebugLogging, "fmi2SetDebugLogging");
  resolve(f.Instantiate, "fmi2Instantiate");
  resolve(f.FreeInstance, "fmi2FreeInstance");
  resolve(f.SetupExperiment, "fmi2SetupExperiment");
  resolve(f.EnterInitializationMode, "fmi2EnterInitializationMode");
  resolve(f.ExitInitializationMode, "fmi2ExitInitializationMode");
  resolve(f.Terminate, "fmi2Terminate");
  resolve(f.Reset, "fmi2Reset");
  resolve(f.GetReal, "fmi2GetReal");
  resolve(f.GetInteger, "fmi2GetInteger");
  resolve(f.GetBoolean, "fmi2GetBoolean");
  resolve(f.GetString, "fmi2GetString");
  resolve(f.SetReal, "fmi2SetReal");
  resolve(f.SetInteger, "fmi2SetInteger");
  resolve(f.SetBoolean, "fmi2SetBoolean");
  resolve(f.SetString, "fmi2SetString");
  resolve(f.GetFMUstate, "fmi2GetFMUstate");
  resolve(f.SetFMUstate, "fmi2SetFMUstate");
  resolve(f.FreeFMUstate, "fmi2FreeFMUstate");
  resolve(f.SerializedFMUstateSize, "fmi2SerializedFMUstateSize");
  resolve(f.SerializeFMUstate, "fmi2SerializeFMUstate");
  resolve(f.DeSerializeFMUstate, "fmi2DeSerializeFMUstate");
  resolve(f.GetDirectionalDerivative, "fmi2GetDirectionalDerivative");
  resolve(f.SetRealInputDerivatives, "fmi2SetRealInputDerivatives");
  resolve(f.GetRealOutputDerivatives, "fmi2GetRealOutputDerivatives");
  resolve(f.DoStep, "fmi2DoStep");
  resolve(f.CancelStep, "fmi2CancelStep");
  resolve(f.GetStatus, "fmi2GetStatus");
  resolve(f.GetRealStatus, "fmi2GetRealStatus");
  resolve(f.GetIntegerStatus, "fmi2GetIntegerStatus");
  resolve(f.GetBooleanStatus, "fmi2GetBooleanStatus");
  resolve(f.GetStringStatus, "fmi2GetStringStatus");
  if (std::strcmp(f.GetVersion(), fmi2Version) != 0 || std::strcmp(f.GetTypesPlatform(), fmi2TypesPlatform) != 0)
    throw std::runtime_error(std::string("the binary is FMI ") + f.GetVersion() + ", platform " + f.GetTypesPlatform());
}

FmiHost::~FmiHost() {
  if (component_ != nullptr && (state_ & (kStepInProgress | kFatal)) == 0) functions_.FreeInstance(component_);
  if (library_ != nullptr) dlclose(library_);
}

void FmiHost::logger(fmi2ComponentEnvironment environment, fmi2String instance, fmi2Status status, fmi2String category,
                     fmi2String message, ...) {
  auto* host = static_cast<FmiHost*>(environment);
  char text[4096];
  va_list arguments;
  va_start(arguments, message);
  std::vsnprintf(text, sizeof text, message != nullptr ? message : "", arguments);
  va_end(arguments);
  host->log_.push_back({instance != nullptr ? instance : "", status, category != nullptr ? category : "", text});
}

std::string FmiHost::state() const {
  static const std::map<unsigned, std::string> names = {{kStartAndEnd, "startAndEnd"},
                                                        {kInstantiated, "instantiated"},
                                                        {kInitialization, "initializationMode"},
                                                        {kStepComplete, "stepComplete"},
                                                        {kStepInProgress, "stepInProgress"},
                                                        {kStepFailed, "stepFailed"},
                                                        {kStepCanceled, "stepCanceled"},
                                                        {kTerminated, "terminated"},
                                                        {kError, "error"},
                                                        {kFatal, "fatal"}};
  return names.at(state_);
}

void FmiHost::allow(const char* function, unsigned allowed) const {
  if ((state_ & allowed) == 0)
    throw HostRefusal(std::string("host: ") + function + " is not allowed in state " + state() +
                      " (FMI 2.0 section 4.2.4)");
}

fmi2Status FmiHost::after(fmi2Status status, unsigned next) {
  if (status == fmi2OK || status == fmi2Warning)
    state_ = next;
  else if (status == fmi2Error)
    state_ = kError;
  else if (status == fmi2Fatal)
    state_ = kFatal;
  return status;
}

std::string FmiHost::resource_uri() const {
  std::string out = "file://";
  for (const unsigned char c : std::filesystem::absolute(dir_ / "resources").string()) {
    if (std::isalnum(c) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') {
      out += static_cast<char>(c);
    } else {
      char escaped[4];
      std::snprintf(escaped, sizeof escaped, "%%%02X", c);
      out += escaped;
    }
  }
  return out;
}

fmi2Status FmiHost::instantiate(const std::string& name, std::optional<std::string> guid,
                                std::optional<std::string> resources) {
  allow("fmi2Instantiate", kStartAndEnd);
  const std::string uri = resources.value_or(resource_uri());
  component_ = functions_.Instantiate(name.c_str(), fmi2CoSimulation, guid.value_or(model_.guid).c_str(), uri.c_str(),
                                      &callbacks_, fmi2False, fmi2False);
  if (component_ == nullptr) return fmi2Error;  // still startAndEnd: nothing was made
  state_ = kInstantiated;
  return fmi2OK;
}

fmi2Status FmiHost::setup_experiment(double start_time) {
  allow("fmi2SetupExperiment", kInstantiated);
  return after(functions_.SetupExperiment(component_, fmi2False, 0.0, start_time, fmi2False, 0.0), kInstantiated);
}

fmi2Status FmiHost::enter_initialization_mode() {
  allow("fmi2EnterInitializationMode", kInstantiated);
  return after(functions_.EnterInitializationMode(component_), kInitialization);
}

fmi2Status FmiHost::exit_initialization_mode() {
  allow("fmi2ExitInitializationMode", kInitialization);
  return after(functions_.ExitInitializationMode(component_), kStepComplete);
}

fmi2Status FmiHost::set_real(const std::vector<fmi2ValueReference>& vr, const std::vector<double>& values) {
  allow("fmi2SetReal", kInstantiated | kInitialization | kStepComplete);
  if (vr.size() != values.size()) throw HostRefusal("host: fmi2SetReal with as many values as references");
  // Inputs at any of these states; fixed parameters before initialisation ends (FMI 2.0.x section 4.2.4).
  const bool parameters_settable = state_ == kInstantiated || state_ == kInitialization;
  for (const fmi2ValueReference r : vr) {
    bool settable = false;
    for (const auto& v : model_.variables)
      settable = settable || (v.value_reference == r &&
                              (v.causality == "input" || (v.causality == "parameter" && parameters_settable)));
    if (!settable)
      throw HostRefusal("host: value reference " + std::to_string(r) +
                        (parameters_settable ? " is not an input or a parameter" : " is not an input"));
  }
  return after(functions_.SetReal(component_, vr.data(), vr.size(), values.data()), state_);
}

fmi2Status FmiHost::get_real(const std::vector<fmi2ValueReference>& vr, std::vector<double>& values) {
  allow("fmi2GetReal", kInitialization | kStepComplete | kStepFailed | kStepCanceled | kTerminated | kError);
  values.assign(vr.size(), 0.0);
  return after(functions_.GetReal(component_, vr.data(), vr.size(), values.data()), state_);
}

fmi2Status FmiHost::do_step(double time, double step) {
  allow("fmi2DoStep", kStepComplete);
  return after(functions_.DoStep(component_, time, step, fmi2True), kStepComplete);
}

fmi2Status FmiHost::terminate() {
  allow("fmi2Terminate", kStepComplete | kStepFailed | kStepCanceled);
  return after(functions_.Terminate(component_), kTerminated);
}

fmi2Status FmiHost::reset() {
  allow("fmi2Reset",
        kInstantiated | kInitialization | kStepComplete | kStepFailed | kStepCanceled | kTerminated | kError);
  return after(functions_.Reset(component_), kInstantiated);
}

void FmiHost::free_instance() {
  allow("fmi2FreeInstance",
        kInstantiated | kInitialization | kStepComplete | kStepFailed | kStepCanceled | kTerminated | kError);
  functions_.FreeInstance(component_);
  component_ = nullptr;
  state_ = kStartAndEnd;
}

}  // namespace hydrocoef::test
