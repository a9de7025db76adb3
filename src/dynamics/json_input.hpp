// Typed reading of the dynamics module's JSON input files (vehicle and
// scenario descriptions) with errors that name the file, the key path, what
// was found and what was expected. Comments (// and /* */) are allowed in the
// files so that a description can say where its numbers come from.
#pragma once

#include <Eigen/Core>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace hydrocoef::json_input {

using Json = nlohmann::json;

/// Parses a whole document; InputError "file:line:column: ..." on a syntax error.
Json parse(std::string_view text, const std::string& file);
/// The bytes of a file; InputError naming it when it cannot be read.
std::string read_file(const std::string& path);

/// "a.b" from "a" and "b"; "b" when path is empty.
std::string join(const std::string& path, std::string_view key);
/// What a JSON value is, for messages: "a number", "a string", "an object", ...
std::string describe(const Json& value);

/// InputError "file: key 'path': message".
[[noreturn]] void fail(const std::string& file, const std::string& path, const std::string& message);

/// Throws unless `value` is an object whose keys are all in `allowed`.
void expect_object(const Json& value, const std::string& file, const std::string& path,
                   std::initializer_list<std::string_view> allowed);
/// The member or nullptr.
const Json* find(const Json& object, std::string_view key);
/// The member; InputError "missing" otherwise.
const Json& require(const Json& object, const std::string& file, const std::string& path, std::string_view key);

/// A finite number.
double number(const Json& value, const std::string& file, const std::string& path);
/// A finite number > 0 (or >= 0 when allow_zero).
double positive(const Json& value, const std::string& file, const std::string& path, bool allow_zero = false);
std::string string(const Json& value, const std::string& file, const std::string& path);
bool boolean(const Json& value, const std::string& file, const std::string& path);
/// An array of exactly n finite numbers (any n when n == 0).
std::vector<double> numbers(const Json& value, const std::string& file, const std::string& path, std::size_t n = 0);
Eigen::Vector3d vector3(const Json& value, const std::string& file, const std::string& path);
/// An n x n matrix as an array of n rows of n numbers.
Eigen::MatrixXd matrix(const Json& value, const std::string& file, const std::string& path, Eigen::Index n);

}  // namespace hydrocoef::json_input
