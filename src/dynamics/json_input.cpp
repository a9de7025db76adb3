#include "src/dynamics/json_input.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "src/core/error.hpp"

namespace hydrocoef::json_input {

Json parse(std::string_view text, const std::string& file) {
  try {
    return Json::parse(text.begin(), text.end(), nullptr, true, true);
  } catch (const Json::parse_error& e) {
    // e.byte is 1-based: the byte where parsing stopped.
    SourceLocation where{file, 1, 1};
    const std::size_t end = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    for (std::size_t i = 0; i < end; ++i) {
      if (text[i] == '\n') {
        ++where.line;
        where.column = 1;
      } else {
        ++where.column;
      }
    }
    std::string message = e.what();
    // nlohmann's message: "[json.exception.parse_error.101] parse error at line 2, column 3: syntax error ..."
    if (const auto colon = message.find(": "); colon != std::string::npos) message = message.substr(colon + 2);
    throw InputError(where, "not valid JSON: " + message);
  } catch (const Json::exception& e) {
    // Anything else the parser rejects, e.g. a number beyond double's range (1e999).
    std::string message = e.what();
    if (const auto bracket = message.find("] "); bracket != std::string::npos) message = message.substr(bracket + 2);
    throw InputError(SourceLocation{file}, "not valid JSON: " + message + "; expected finite numbers");
  }
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLocation{path}, "cannot read the file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string join(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string describe(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::object: return "an object";
    case Json::value_t::array: return "an array of " + std::to_string(value.size());
    case Json::value_t::string: return "the string \"" + value.get<std::string>() + "\"";
    case Json::value_t::boolean: return value.get<bool>() ? "true" : "false";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float: return value.dump();
    default: return "an unsupported value";
  }
}

void fail(const std::string& file, const std::string& path, const std::string& message) {
  throw InputError(SourceLocation{file}, "key '" + path + "': " + message);
}

void expect_object(const Json& value, const std::string& file, const std::string& path,
                   std::initializer_list<std::string_view> allowed) {
  if (!value.is_object())
    fail(file, path.empty() ? "(top level)" : path, "found " + describe(value) + ", expected an object");
  for (const auto& item : value.items()) {
    bool known = false;
    for (const auto& a : allowed) known = known || item.key() == a;
    if (!known) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      fail(file, join(path, item.key()), "unknown key, expected one of: " + list);
    }
  }
}

const Json* find(const Json& object, std::string_view key) {
  const auto it = object.find(std::string(key));
  return it == object.end() ? nullptr : &*it;
}

const Json& require(const Json& object, const std::string& file, const std::string& path, std::string_view key) {
  const Json* member = find(object, key);
  if (!member) fail(file, join(path, key), "missing");
  return *member;
}

double number(const Json& value, const std::string& file, const std::string& path) {
  if (!value.is_number()) fail(file, path, "found " + describe(value) + ", expected a number");
  const double x = value.get<double>();
  if (!std::isfinite(x)) fail(file, path, "found " + value.dump() + ", expected a finite number");
  return x;
}

double positive(const Json& value, const std::string& file, const std::string& path, bool allow_zero) {
  const double x = number(value, file, path);
  if (allow_zero ? x < 0.0 : x <= 0.0)
    fail(file, path,
         "found " + value.dump() + ", expected a " + (allow_zero ? "non-negative" : "positive") + " number");
  return x;
}

std::string string(const Json& value, const std::string& file, const std::string& path) {
  if (!value.is_string()) fail(file, path, "found " + describe(value) + ", expected a string");
  return value.get<std::string>();
}

bool boolean(const Json& value, const std::string& file, const std::string& path) {
  if (!value.is_boolean()) fail(file, path, "found " + describe(value) + ", expected true or false");
  return value.get<bool>();
}

std::vector<double> numbers(const Json& value, const std::string& file, const std::string& path, std::size_t n) {
  if (!value.is_array() || (n != 0 && value.size() != n))
    fail(file, path,
         "found " + describe(value) + ", expected an array of " + (n ? std::to_string(n) + " numbers" : "numbers"));
  std::vector<double> out;
  for (std::size_t i = 0; i < value.size(); ++i)
    out.push_back(number(value[i], file, path + "[" + std::to_string(i) + "]"));
  return out;
}

Eigen::Vector3d vector3(const Json& value, const std::string& file, const std::string& path) {
  const auto v = numbers(value, file, path, 3);
  return {v[0], v[1], v[2]};
}

Eigen::MatrixXd matrix(const Json& value, const std::string& file, const std::string& path, Eigen::Index n) {
  const auto size = static_cast<std::size_t>(n);
  if (!value.is_array() || value.size() != size)
    fail(file, path,
         "found " + describe(value) + ", expected " + std::to_string(n) + " rows of " + std::to_string(n) + " numbers");
  Eigen::MatrixXd m(n, n);
  for (std::size_t i = 0; i < size; ++i) {
    const auto row = numbers(value[i], file, path + "[" + std::to_string(i) + "]", size);
    for (std::size_t j = 0; j < size; ++j) m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = row[j];
  }
  return m;
}

}  // namespace hydrocoef::json_input
