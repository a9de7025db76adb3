#include "importers/openfoam_dictionary.hpp"

#include <charconv>
#include <cmath>

#include "src/core/error.hpp"
#include "src/core/file_bytes.hpp"

namespace hydrocoef {

class FoamParser {
 public:
  FoamParser(std::string_view text, const std::filesystem::path& file, int depth)
      : text_(text), file_(file), depth_(depth) {}

  void parse_into(FoamDictionary& dictionary, bool nested) {
    for (;;) {
      skip_space();
      if (at_ >= text_.size()) {
        if (nested) fail("the file ends inside a dictionary; expected '}'");
        return;
      }
      if (text_[at_] == '}') {
        if (!nested) fail("'}' without its '{'");
        ++at_;
        return;
      }
      if (text_[at_] == ';') {  // a stray ';' is allowed
        ++at_;
        continue;
      }
      const std::size_t line = line_;
      std::string key = token();
      if (key.empty()) fail("expected a keyword");
      if (key[0] == '#') {
        directive(dictionary, key, line);
        continue;
      }
      if (key[0] == '"') key = key.substr(1, key.size() - 2);
      skip_space();
      if (at_ < text_.size() && text_[at_] == '{') {
        ++at_;
        auto child = std::make_shared<FoamDictionary>();
        child->file_ = file_.string();
        child->parent_ = &dictionary;
        parse_into(*child, true);
        if (!dictionary.dictionaries_.count(key)) dictionary.dictionary_order_.push_back(key);
        dictionary.dictionaries_[key] = std::move(child);
        continue;
      }
      FoamValue value{{}, file_.string(), line};
      int parentheses = 0;
      for (;;) {
        skip_space();
        if (at_ >= text_.size()) fail("the entry '" + printable_text(key, 40) + "' has no ';'", line);
        const char c = text_[at_];
        if (c == ';' && parentheses == 0) {
          ++at_;
          break;
        }
        if (c == '{' || c == '}' || c == ';') {
          // Inside a list, dictionaries and their ';' are part of the value
          // (fieldAverage's "fields ( p { mean on; } );").
          if (parentheses == 0)
            fail("unexpected '" + std::string(1, c) + "' in the entry '" + printable_text(key, 40) + "'");
          value.tokens.emplace_back(1, c);
          ++at_;
          continue;
        }
        if (c == '(') ++parentheses;
        if (c == ')' && --parentheses < 0) fail("')' without its '(' in the entry '" + printable_text(key, 40) + "'");
        std::string word = token();
        if (!word.empty() && word[0] == '#')
          fail("the directive '" + printable_text(word, 40) + "' in the entry '" + printable_text(key, 40) +
               "' is not one hydrocoef reads; expected plain values");
        if (!word.empty() && word[0] == '$') {
          const FoamValue* referenced = resolve(dictionary, word.substr(1));
          if (!referenced)
            fail("'" + printable_text(word, 40) + "' refers to no entry of this or an enclosing dictionary");
          value.tokens.insert(value.tokens.end(), referenced->tokens.begin(), referenced->tokens.end());
          continue;
        }
        value.tokens.push_back(std::move(word));
        if (value.tokens.size() > 100000) fail("the entry '" + printable_text(key, 40) + "' is too long", line);
      }
      dictionary.values_[key] = std::move(value);
    }
  }

 private:
  [[noreturn]] void fail(const std::string& message, std::size_t line = 0) const {
    throw InputError(SourceLocation{file_.string(), line ? line : line_, 0}, message);
  }

  void skip_space() {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '\n') {
        ++line_;
        ++at_;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++at_;
      } else if (text_.compare(at_, 2, "//") == 0) {
        while (at_ < text_.size() && text_[at_] != '\n') ++at_;
      } else if (text_.compare(at_, 2, "/*") == 0) {
        const std::size_t end = text_.find("*/", at_ + 2);
        if (end == std::string_view::npos) fail("a comment '/*' is not closed");
        for (std::size_t i = at_; i < end; ++i) line_ += text_[i] == '\n';
        at_ = end + 2;
      } else {
        return;
      }
    }
  }

  /// One token: a punctuation character, a quoted string (with its quotes), or a word.
  std::string token() {
    skip_space();
    if (at_ >= text_.size()) return {};
    const char c = text_[at_];
    if (c == '(' || c == ')' || c == '[' || c == ']') {
      ++at_;
      return std::string(1, c);
    }
    if (c == '"') {
      const std::size_t end = text_.find('"', at_ + 1);
      if (end == std::string_view::npos) fail("a string '\"' is not closed");
      std::string out(text_.substr(at_, end + 1 - at_));
      for (const char ch : out) line_ += ch == '\n';
      at_ = end + 1;
      return out;
    }
    const std::size_t start = at_;
    while (at_ < text_.size()) {
      const char ch = text_[at_];
      if (ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r' || ch == ';' || ch == '(' || ch == ')' || ch == '{' ||
          ch == '}' || ch == '[' || ch == ']' || ch == '"')
        break;
      ++at_;
    }
    if (at_ == start) fail("unexpected '" + std::string(1, c) + "'");
    return std::string(text_.substr(start, at_ - start));
  }

  void directive(FoamDictionary& dictionary, const std::string& name, std::size_t line) {
    if (name == "#include" || name == "#includeIfPresent" || name == "#sinclude") {
      std::string target = token();
      if (target.size() < 2 || target.front() != '"') fail("#include needs a file name in quotes", line);
      target = target.substr(1, target.size() - 2);
      const std::filesystem::path path = file_.parent_path() / target;
      if (name != "#include" && !std::filesystem::exists(path)) return;
      if (depth_ >= 8) fail("#include nested more than 8 deep", line);
      const FoamDictionary included = FoamDictionary::read_nested(path, depth_ + 1);
      for (const auto& [key, value] : included.values_) dictionary.values_[key] = value;
      for (const auto& key : included.dictionary_order_) {
        if (!dictionary.dictionaries_.count(key)) dictionary.dictionary_order_.push_back(key);
        dictionary.dictionaries_[key] = included.dictionaries_.at(key);
      }
      return;
    }
    if (name == "#includeEtc" || name == "#includeFunc" || name == "#includeModel") {
      // Files of the installation: not read. The rest of the line is its argument.
      const std::size_t end = text_.find('\n', at_);
      std::string argument(text_.substr(at_, end == std::string_view::npos ? std::string_view::npos : end - at_));
      at_ = end == std::string_view::npos ? text_.size() : end;
      dictionary.unread_includes_.push_back(name + " " + printable_text(argument, 80));
      return;
    }
    if (name == "#inputMode" || name == "#remove") {
      (void)token();
      return;
    }
    fail("the directive '" + printable_text(name, 40) +
             "' is not one hydrocoef reads (it reads #include, #includeEtc and #includeFunc); expected plain entries",
         line);
  }

  const FoamValue* resolve(const FoamDictionary& dictionary, std::string name) const {
    if (!name.empty() && name.front() == '{' && name.back() == '}') name = name.substr(1, name.size() - 2);
    for (const FoamDictionary* d = &dictionary; d; d = d->parent_)
      if (const FoamValue* found = d->value(name)) return found;
    return nullptr;
  }

  std::string_view text_;
  std::filesystem::path file_;
  int depth_;
  std::size_t at_ = 0;
  std::size_t line_ = 1;
};

FoamDictionary FoamDictionary::read(const std::filesystem::path& file) { return read_nested(file, 0); }

FoamDictionary FoamDictionary::read_nested(const std::filesystem::path& file, int depth) {
  // Dictionaries are small; a large file here is not one.
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  if (!ec && size > (std::uintmax_t{16} << 20))
    throw InputError(SourceLocation{file.string()},
                     "is " + std::to_string(size) + " bytes; expected an OpenFOAM dictionary of at most 16 MB");
  const FileBytes bytes(file);
  return parse(bytes.view(), file, depth);
}

FoamDictionary FoamDictionary::parse(std::string_view text, const std::filesystem::path& file, int depth) {
  FoamDictionary dictionary;
  dictionary.file_ = file.string();
  FoamParser(text, file, depth).parse_into(dictionary, false);
  return dictionary;
}

const FoamValue* FoamDictionary::value(std::string_view key) const {
  const auto found = values_.find(key);
  return found == values_.end() ? nullptr : &found->second;
}

const FoamDictionary* FoamDictionary::dictionary(std::string_view key) const {
  const auto found = dictionaries_.find(key);
  return found == dictionaries_.end() ? nullptr : found->second.get();
}

namespace {

std::optional<double> number(const std::string& text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::string entry_text(const FoamValue& value) {
  std::string text;
  for (const auto& token : value.tokens) text += (text.empty() ? "" : " ") + token;
  return printable_text(text, 60);
}

}  // namespace

double foam_scalar(const FoamValue& value, std::string_view what) {
  // An optional dimension set "[0 2 -1 0 0 0 0]" (and an old-style name before it) precedes the number.
  std::vector<std::string> rest;
  bool in_dimensions = false;
  for (const auto& token : value.tokens) {
    if (token == "[")
      in_dimensions = true;
    else if (token == "]")
      in_dimensions = false;
    else if (!in_dimensions)
      rest.push_back(token);
  }
  if (!rest.empty()) {
    if (const auto x = number(rest.back())) return *x;
  }
  throw InputError(SourceLocation{value.file, value.line, 0},
                   std::string(what) + " is '" + entry_text(value) + "'; expected one number");
}

std::array<double, 3> foam_vector(const FoamValue& value, std::string_view what) {
  std::vector<std::string> tokens = value.tokens;
  if (!tokens.empty() && tokens.front() == "uniform") tokens.erase(tokens.begin());
  if (tokens.size() == 5 && tokens[0] == "(" && tokens[4] == ")") {
    std::array<double, 3> out{};
    bool ok = true;
    for (int i = 0; i < 3; ++i) {
      const auto x = number(tokens[static_cast<std::size_t>(i) + 1]);
      ok = ok && x.has_value();
      if (x) out[static_cast<std::size_t>(i)] = *x;
    }
    if (ok) return out;
  }
  throw InputError(SourceLocation{value.file, value.line, 0},
                   std::string(what) + " is '" + entry_text(value) +
                       "'; expected a uniform vector such as 'uniform (0.1 0 0)' or '(0 0 0)'");
}

std::optional<std::string> foam_word(const FoamValue* value) {
  if (!value || value->tokens.size() != 1) return std::nullopt;
  return value->tokens.front();
}

}  // namespace hydrocoef
