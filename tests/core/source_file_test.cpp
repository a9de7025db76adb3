// Source files: SHA-256 against the FIPS 180-2 test vectors, and loading a
// file byte for byte (binary content, more than one read buffer) with its
// hash, or an InputError naming the path.
#include "src/core/source_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "src/core/error.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

namespace fs = std::filesystem;

TEST(Sha256Hex, Fips180_2OneBlockMessage) {
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(Sha256Hex, EmptyString) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(Sha256Hex, Fips180_2MultiBlockMessage) {
  // The 448-bit message of FIPS 180-2 appendix B.2.
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(Sha256Hex, Fips180_2LongMessage) {
  // Appendix B.3: one million repetitions of 'a'.
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256Hex, HashesEmbeddedNulBytes) {
  const std::string with_nul("abc\0", 4);
  EXPECT_NE(sha256_hex(with_nul), sha256_hex("abc"));
  EXPECT_EQ(sha256_hex(with_nul).size(), 64u);
}

// A fresh directory under the system temp directory, removed at the end.
class TempDir {
 public:
  explicit TempDir(const std::string& tag)
      : path_(fs::temp_directory_path() / ("hydrocoef-source-file-" + tag + "-" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

void write_file(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  ASSERT_TRUE(out.good()) << path;
}

TEST(LoadSourceFile, SmallFileBytesAndHash) {
  TempDir dir("small");
  const fs::path path = dir.path() / "table.csv";
  write_file(path, "abc");
  const SourceFile file = load_source_file(path);
  EXPECT_EQ(file.path, path);
  EXPECT_EQ(file.bytes, "abc");
  EXPECT_EQ(file.sha256, "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(LoadSourceFile, EmptyFile) {
  TempDir dir("empty");
  const fs::path path = dir.path() / "empty.csv";
  write_file(path, "");
  const SourceFile file = load_source_file(path);
  EXPECT_EQ(file.bytes, "");
  EXPECT_EQ(file.sha256, "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(LoadSourceFile, BinaryContentLargerThanOneBufferIsKeptExactly) {
  TempDir dir("large");
  const fs::path path = dir.path() / "big.bin";
  std::string bytes;
  // 200000 bytes: every byte value, CR, LF, NUL; longer than the 64 KiB read buffer.
  for (std::size_t i = 0; i < 200000; ++i) bytes += static_cast<char>((i * 7 + i / 256) % 256);
  bytes += std::string("\r\n\0tail", 7);
  write_file(path, bytes);
  const SourceFile file = load_source_file(path);
  ASSERT_EQ(file.bytes.size(), bytes.size());
  EXPECT_TRUE(file.bytes == bytes);
  EXPECT_EQ(file.sha256, sha256_hex(bytes));
}

TEST(LoadSourceFile, MissingPathIsAnInputErrorNamingIt) {
  TempDir dir("missing");
  const fs::path path = dir.path() / "no-such-table.csv";
  try {
    (void)load_source_file(path);
    FAIL() << "a missing file was loaded";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_EQ(error.where().file, path.string());
  }
}

TEST(LoadSourceFile, DirectoryIsAnInputErrorNamingIt) {
  TempDir dir("directory");
  try {
    (void)load_source_file(dir.path());
    FAIL() << "a directory was loaded";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(dir.path().string()), std::string::npos) << message;
    EXPECT_NE(message.find("directory"), std::string::npos) << message;
  }
}

TEST(LoadSourceFile, RealExampleHashMatchesItsBytes) {
  const fs::path path = fs::path(HYDROCOEF_SOURCE_DIR) / "examples/asr-v/asr-v-surge-damping.csv";
  std::ifstream in(path, std::ios::binary);
  ASSERT_TRUE(in) << path;
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const SourceFile file = load_source_file(path);
  EXPECT_EQ(file.bytes, bytes);
  EXPECT_EQ(file.sha256, sha256_hex(bytes));
}

}  // namespace
}  // namespace hydrocoef

namespace hydrocoef {
namespace {

TEST(DigestFile, StreamsTheSameHashAsTheWholeBytesAcrossManyBlocks) {
  test::TempDir dir;
  // 200 KiB + 7 bytes: several 64 KiB read blocks and a short last one.
  std::string bytes(200 * 1024 + 7, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>((i * 2654435761u) >> 13);
  const auto path = dir / "big.bin";
  std::ofstream(path, std::ios::binary) << bytes;
  const FileDigest digest = digest_file(path);
  EXPECT_EQ(digest.sha256, sha256_hex(bytes));
  EXPECT_EQ(digest.size_bytes, bytes.size());
  EXPECT_EQ(digest.sha256, load_source_file(path).sha256);
  // An empty file hashes to SHA-256 of nothing.
  std::ofstream(dir / "empty.bin", std::ios::binary).close();
  EXPECT_EQ(digest_file(dir / "empty.bin").sha256, "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  try {
    digest_file(dir / "missing.bin");
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("missing.bin"), std::string::npos) << error.what();
  }
  EXPECT_THROW(digest_file(dir.path()), InputError);
}

}  // namespace
}  // namespace hydrocoef
