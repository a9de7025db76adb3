// What libhydrocoef.so exports (cmake/hydrocoef.map): the public API of
// include/hydrocoef/ and nothing else. Read with `nm -D --defined-only -C`,
// as a packager or an ABI checker reads it: every defined dynamic symbol is a
// member of hydrocoef::api, hydrocoef::InputError, or their type information;
// the calls a library user makes are among them; none of the internals (the
// store, the surfaces, VTK's and the standard library's template instances)
// is. Runs in the optimized build, which makes the shared library.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace {

std::vector<std::string> exported_symbols() {
  const std::string command = "nm -D --defined-only -C '" + std::string(HYDROCOEF_SHARED_LIBRARY) + "' 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return {};
  std::vector<std::string> names;
  char line[4096];
  while (std::fgets(line, sizeof line, pipe.get())) {
    std::string text(line);
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    // "ADDRESS TYPE NAME"
    const auto first = text.find(' '), second = first == std::string::npos ? first : text.find(' ', first + 1);
    if (second == std::string::npos) {
      names.push_back("(unreadable nm line) " + text);
      continue;
    }
    names.push_back(text.substr(second + 1));
  }
  return names;
}

bool public_name(const std::string& name) {
  for (const char* prefix :
       {"hydrocoef::api::", "hydrocoef::InputError::", "typeinfo for hydrocoef::api::",
        "typeinfo name for hydrocoef::api::", "vtable for hydrocoef::api::", "typeinfo for hydrocoef::InputError",
        "typeinfo name for hydrocoef::InputError", "vtable for hydrocoef::InputError"})
    if (name.rfind(prefix, 0) == 0) return true;
  return false;
}

TEST(ExportedSymbols, TheSharedLibraryExportsThePublicApiAndNothingElse) {
  const auto names = exported_symbols();
  ASSERT_GT(names.size(), 20u) << "nm read nothing from " << HYDROCOEF_SHARED_LIBRARY;
  std::vector<std::string> internal;
  for (const auto& name : names)
    if (!public_name(name)) internal.push_back(name);
  EXPECT_TRUE(internal.empty()) << internal.size() << " symbols outside the public API, the first: "
                                << (internal.empty() ? "" : internal.front());
  // What a user of the public headers calls is there.
  for (const char* wanted :
       {"hydrocoef::api::Database::Database(", "hydrocoef::api::Surface::evaluate(", "hydrocoef::api::Database::fit(",
        "hydrocoef::InputError::InputError(", "typeinfo for hydrocoef::InputError"}) {
    bool found = false;
    for (const auto& name : names) found = found || name.rfind(wanted, 0) == 0;
    EXPECT_TRUE(found) << wanted;
  }
}

}  // namespace
