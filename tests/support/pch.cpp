// The translation unit that builds the tests' precompiled header
// (tests/CMakeLists.txt: gtest, nlohmann::json and the standard headers
// nearly every test includes), reused by every test executable.
