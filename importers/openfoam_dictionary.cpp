// OpenFOAM dictionaries as hydrocoef reads them (see the header for the
// grammar). What is read as OpenFOAM reads it, and what more strictly:
//  - As OpenFOAM: a '}' without its '{' at the top level of a file ends that
//    file's dictionary and the rest is not read (OpenFOAM-10
//    dictionary::read stops where entry::New meets the '}'; a controlDict
//    with a stray '}' after its last entry runs). It is kept as a warning.
//    Stray ';' are skipped, as entry::getKeyword skips them.
//  - Strictly, because the alternative is a wrong setting rather than a
//    missing one: a file that ends inside a dictionary, an entry without its
//    ';' or a comment or string that is not closed is refused (OpenFOAM may
//    read a file cut short up to where it stops; a case file cut short is
//    damaged, and its last entries could be read half); a `$` reference to
//    no entry is refused (OpenFOAM stops there too); directives hydrocoef
//    cannot evaluate (#calc, #codeStream, #if...) are refused rather than
//    skipped.
//  - Bounded, because a received case is untrusted (FoamReadLimits in the
//    header, with its defaults): dictionary nesting (the parser recurses per
//    level, so 20,000 levels would overflow the stack), the tokens `$`
//    references copy (counted before they are copied), each entry's tokens,
//    each file's bytes, and the number and bytes of included files.
//  - #include reaches regular files inside the case folder only: the name is
//    resolved (symbolic links too) and checked before the file is opened, so
//    an absolute name, a `..` leading out of the case, /dev/zero or a FIFO is
//    refused without being read, and nothing of a file outside the case is
//    ever quoted. `$FOAM_CASE/` and `<case>/`, `<system>/`, `<constant>/` at
//    the start of a name mean the case folder and its system and constant
//    folders. #includeEtc and #includeFunc (the installation's files) are
//    recorded, not read.
#include "importers/openfoam_dictionary.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <optional>
#include <system_error>

#include "src/core/error.hpp"

namespace hydrocoef {

namespace fs = std::filesystem;

namespace {

/// The bytes of a regular file of at most max_bytes: refused before it is
/// opened when it is not a regular file (a FIFO would block, a device never
/// end), opened without blocking and checked again on the open descriptor.
/// Messages are at `where`, after `lead` ("" or "#include \"x\": ").
std::string read_regular_file(const fs::path& file, std::uintmax_t max_bytes, const SourceLocation& where,
                              const std::string& lead) {
  const auto error = [&](const std::string& what) { return InputError(where, lead + what); };
  const std::string not_regular = "is not a regular file (a folder, FIFO or device); expected a dictionary file";
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (!fs::exists(status)) throw error("no such file");
  if (!fs::is_regular_file(status)) throw error(not_regular);
  const int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw error(std::string("cannot open: ") + std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat info {};
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) throw error(not_regular);
  const auto too_large = [&](std::uintmax_t size) {
    return error("is " + std::to_string(size) + " bytes; expected an OpenFOAM dictionary of at most " +
                 std::to_string(max_bytes) + " bytes");
  };
  const auto stated = static_cast<std::uintmax_t>(info.st_size);
  if (stated > max_bytes) throw too_large(stated);
  std::string bytes(static_cast<std::size_t>(stated) + 1, '\0');  // one more: a file that grew is seen
  std::size_t got = 0;
  for (;;) {
    if (got == bytes.size()) {
      if (got > max_bytes) throw too_large(got);
      bytes.resize(static_cast<std::size_t>(std::min<std::uintmax_t>(max_bytes + 1, 2 * std::uintmax_t{got} + 4096)));
    }
    const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw error(std::string("read error: ") + std::strerror(errno));
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  if (got > max_bytes) throw too_large(got);
  bytes.resize(got);
  return bytes;
}

/// `path` below `folder` (both absolute and free of symbolic links and
/// `..`), or the folder itself.
bool is_inside(const fs::path& path, const fs::path& folder) {
  const fs::path relative = path.lexically_relative(folder);
  return !relative.empty() && *relative.begin() != "..";
}

}  // namespace

/// What one read (a file and its #includes) shares: the case folder and the
/// budgets of FoamReadLimits spent so far.
struct FoamReadState {
  FoamReadLimits limits;
  fs::path case_dir;           ///< as given or inferred
  fs::path case_dir_resolved;  ///< canonical; empty when it cannot be resolved
  std::size_t nesting = 0;
  std::size_t expanded_tokens = 0;
  std::size_t included_files = 0;
  std::uintmax_t included_bytes = 0;
  std::vector<std::string>* warnings = nullptr;
};

class FoamParser {
 public:
  FoamParser(std::string_view text, const fs::path& file, int depth, FoamReadState& state)
      : text_(text), file_(file), file_name_(file.string()), depth_(depth), state_(state) {}

  void parse_into(FoamDictionary& dictionary, bool nested) {
    for (;;) {
      skip_space();
      if (at_ >= text_.size()) {
        if (nested) fail("the file ends inside a dictionary; expected '}'");
        return;
      }
      if (text_[at_] == '}') {
        ++at_;
        if (!nested) stray_brace();
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
        if (state_.nesting >= state_.limits.max_nesting)
          fail("dictionaries nested more than " + std::to_string(state_.limits.max_nesting) +
               " deep; expected at most " + std::to_string(state_.limits.max_nesting) +
               " (OpenFOAM's cases nest a few levels)");
        ++at_;
        auto child = std::make_shared<FoamDictionary>();
        child->file_ = file_name_;
        child->parent_ = &dictionary;
        ++state_.nesting;
        parse_into(*child, true);
        --state_.nesting;
        if (!dictionary.dictionaries_.count(key)) dictionary.dictionary_order_.push_back(key);
        dictionary.dictionaries_[key] = std::move(child);
        continue;
      }
      FoamValue value{{}, file_name_, line};
      const std::size_t max_tokens = state_.limits.max_entry_tokens;
      const auto too_long = [&] {
        fail("the entry '" + printable_text(key, 40) + "' has more than " + std::to_string(max_tokens) +
                 " tokens; expected at most " + std::to_string(max_tokens),
             line);
      };
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
          if (value.tokens.size() > max_tokens) too_long();
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
          // Counted before anything is copied.
          const std::size_t count = referenced->tokens.size();
          if (count > state_.limits.max_expanded_tokens - state_.expanded_tokens)
            fail("the $ references of this dictionary and its #includes expand to more than " +
                 std::to_string(state_.limits.max_expanded_tokens) + " tokens (at '" + printable_text(word, 40) +
                 "'); expected at most " + std::to_string(state_.limits.max_expanded_tokens));
          if (count > max_tokens - value.tokens.size()) too_long();
          state_.expanded_tokens += count;
          value.tokens.insert(value.tokens.end(), referenced->tokens.begin(), referenced->tokens.end());
          continue;
        }
        value.tokens.push_back(std::move(word));
        if (value.tokens.size() > max_tokens) too_long();
      }
      dictionary.values_[key] = std::move(value);
    }
  }

 private:
  [[noreturn]] void fail(const std::string& message, std::size_t line = 0) const {
    throw InputError(SourceLocation{file_name_, line ? line : line_, 0}, message);
  }

  /// A '}' without its '{' at the top level of a file: OpenFOAM's
  /// dictionary::read ends there (entry::New returns false at END_BLOCK),
  /// and so does this read, with a warning.
  void stray_brace() {
    const std::size_t brace_line = line_;
    const bool more = text_.find_first_not_of(" \t\r\n\f\v", at_) != std::string_view::npos;
    if (state_.warnings)
      state_.warnings->push_back(file_name_ + ":" + std::to_string(brace_line) +
                                 ": a '}' without its '{' ends the dictionary here, as OpenFOAM reads it" +
                                 (more ? "; the text after it is not read" : ""));
    at_ = text_.size();
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

  /// The file an #include names, resolved and checked, or nullopt for an
  /// optional include of a file that does not exist. Nothing is opened here.
  std::optional<fs::path> include_target(const std::string& directive, const std::string& target, std::size_t line) {
    const std::string shown = directive + " \"" + printable_text(target, 80) + "\"";
    const auto refuse = [&](const std::string& why) { fail(shown + ": " + why, line); };
    if (target.empty()) refuse("an empty file name; expected a file of the case");
    fs::path path;
    std::string_view rest = target;
    const auto prefixed = [&](std::string_view prefix) {
      if (!rest.starts_with(prefix)) return false;
      rest.remove_prefix(prefix.size());
      while (!rest.empty() && rest.front() == '/') rest.remove_prefix(1);
      return true;
    };
    if (prefixed("$FOAM_CASE/") || prefixed("<case>/"))
      path = state_.case_dir / fs::path(rest);
    else if (prefixed("<system>/"))
      path = state_.case_dir / "system" / fs::path(rest);
    else if (prefixed("<constant>/"))
      path = state_.case_dir / "constant" / fs::path(rest);
    else if (fs::path(target).is_absolute())
      refuse("an absolute file name; expected a file inside the case folder, named relative to this file");
    else
      path = file_.parent_path() / fs::path(target);
    if (target.find('$') != std::string::npos && !target.starts_with("$FOAM_CASE/"))
      refuse("a name with a variable other than $FOAM_CASE; expected a file of the case");
    if (state_.case_dir_resolved.empty())
      refuse("the case folder '" + printable_text(state_.case_dir.string(), 80) +
             "' cannot be resolved; expected an existing case folder");
    std::error_code ec;
    const fs::file_status link = fs::symlink_status(path, ec);
    if (ec || !fs::exists(link)) {
      if (directive != "#include") return std::nullopt;  // #includeIfPresent, #sinclude
      refuse("no such file");
    }
    const fs::path resolved = fs::canonical(path, ec);
    if (ec) {
      if (directive != "#include" && ec == std::errc::no_such_file_or_directory) return std::nullopt;
      refuse("cannot be resolved (" + ec.message() + ")");
    }
    if (!is_inside(resolved, state_.case_dir_resolved))
      refuse("names a file outside the case folder '" + printable_text(state_.case_dir.string(), 80) +
             "'; expected a file inside it");
    const fs::file_status status = fs::status(resolved, ec);
    if (ec || !fs::is_regular_file(status))
      refuse("is not a regular file (a folder, FIFO or device); expected a dictionary file of the case");
    return resolved;
  }

  void directive(FoamDictionary& dictionary, const std::string& name, std::size_t line) {
    if (name == "#include" || name == "#includeIfPresent" || name == "#sinclude") {
      std::string target = token();
      if (target.size() < 2 || target.front() != '"') fail("#include needs a file name in quotes", line);
      target = target.substr(1, target.size() - 2);
      if (depth_ >= state_.limits.max_include_depth)
        fail("#include nested more than " + std::to_string(state_.limits.max_include_depth) +
                 " deep; expected at most " + std::to_string(state_.limits.max_include_depth),
             line);
      const auto path = include_target(name, target, line);
      if (!path) return;
      const SourceLocation where{file_name_, line, 0};
      const std::string shown = name + " \"" + printable_text(target, 80) + "\"";
      if (state_.included_files >= state_.limits.max_included_files)
        throw InputError(where, shown + ": more than " + std::to_string(state_.limits.max_included_files) +
                                    " files included in one read; expected at most " +
                                    std::to_string(state_.limits.max_included_files));
      ++state_.included_files;
      const std::uintmax_t left = state_.limits.max_included_bytes - state_.included_bytes;
      std::error_code ec;
      const std::uintmax_t size = fs::file_size(*path, ec);
      if (!ec && size > left)
        throw InputError(where,
                         shown + ": the included files pass " + std::to_string(state_.limits.max_included_bytes) +
                             " bytes together; expected at most " + std::to_string(state_.limits.max_included_bytes));
      const std::string bytes =
          read_regular_file(*path, std::min(left, state_.limits.max_file_bytes), where, shown + ": ");
      state_.included_bytes += bytes.size();
      // Read into this dictionary, as OpenFOAM's includeEntry does.
      FoamParser(bytes, *path, depth_ + 1, state_).parse_into(dictionary, false);
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
  fs::path file_;
  std::string file_name_;
  int depth_;
  FoamReadState& state_;
  std::size_t at_ = 0;
  std::size_t line_ = 1;
};

namespace {

FoamReadState read_state(const fs::path& file, const fs::path& case_dir, const FoamReadLimits& limits) {
  FoamReadState state;
  state.limits = limits;
  std::error_code ec;
  if (!case_dir.empty()) {
    state.case_dir = case_dir;
  } else {
    const fs::path absolute = fs::absolute(file, ec);
    state.case_dir = ec ? file.parent_path().parent_path() : absolute.parent_path().parent_path();
  }
  const fs::path resolved = fs::canonical(state.case_dir, ec);
  if (!ec && fs::is_directory(resolved, ec)) state.case_dir_resolved = resolved;
  return state;
}

}  // namespace

FoamDictionary FoamDictionary::read(const fs::path& file, const fs::path& case_dir, const FoamReadLimits& limits) {
  // Dictionaries are small; a large file here is not one.
  const std::string bytes = read_regular_file(file, limits.max_file_bytes, SourceLocation{file.string()}, "");
  return parse(bytes, file, case_dir, limits);
}

FoamDictionary FoamDictionary::parse(std::string_view text, const fs::path& file, const fs::path& case_dir,
                                     const FoamReadLimits& limits) {
  FoamDictionary dictionary;
  dictionary.file_ = file.string();
  FoamReadState state = read_state(file, case_dir, limits);
  state.warnings = &dictionary.warnings_;
  FoamParser(text, file, 0, state).parse_into(dictionary, false);
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
