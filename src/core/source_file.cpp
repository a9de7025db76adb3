#include "src/core/source_file.hpp"

#include <openssl/evp.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "src/core/error.hpp"

namespace hydrocoef {

namespace {

constexpr char kHex[] = "0123456789abcdef";

std::string to_hex(const unsigned char* digest, unsigned int length) {
  std::string out;
  out.reserve(2 * length);
  for (unsigned int i = 0; i < length; ++i) {
    out += kHex[digest[i] >> 4];
    out += kHex[digest[i] & 0x0f];
  }
  return out;
}

/// Opens a file for reading, with the errors both readers give, and hands
/// each block of its bytes to `consume`.
template <typename Consume>
void read_blocks(const std::filesystem::path& path, Consume consume) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(SourceLocation{path.string()}, "no such file");
  if (std::filesystem::is_directory(path, ec))
    throw InputError(SourceLocation{path.string()}, "is a directory, expected a file");
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw InputError(SourceLocation{path.string()}, std::string("cannot open: ") + std::strerror(errno));
  std::array<char, 1 << 16> buffer{};
  std::size_t got = 0;
  while ((got = std::fread(buffer.data(), 1, buffer.size(), file.get())) > 0) consume(buffer.data(), got);
  if (std::ferror(file.get()))
    throw InputError(SourceLocation{path.string()}, std::string("read error: ") + std::strerror(errno));
}

}  // namespace

std::string sha256_hex(std::string_view bytes) {
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned int length = 0;
  if (EVP_Digest(bytes.data(), bytes.size(), digest.data(), &length, EVP_sha256(), nullptr) != 1)
    throw std::runtime_error("SHA-256 computation failed in libcrypto");
  return to_hex(digest.data(), length);
}

SourceFile load_source_file(const std::filesystem::path& path) {
  SourceFile out;
  out.path = path;
  read_blocks(path, [&](const char* data, std::size_t size) { out.bytes.append(data, size); });
  out.sha256 = sha256_hex(out.bytes);
  return out;
}

FileDigest digest_file(const std::filesystem::path& path) {
  std::unique_ptr<EVP_MD_CTX, void (*)(EVP_MD_CTX*)> context(EVP_MD_CTX_new(), &EVP_MD_CTX_free);
  if (!context || EVP_DigestInit_ex(context.get(), EVP_sha256(), nullptr) != 1)
    throw std::runtime_error("SHA-256 initialisation failed in libcrypto");
  FileDigest out;
  read_blocks(path, [&](const char* data, std::size_t size) {
    if (EVP_DigestUpdate(context.get(), data, size) != 1)
      throw std::runtime_error("SHA-256 computation failed in libcrypto");
    out.size_bytes += size;
  });
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned int length = 0;
  if (EVP_DigestFinal_ex(context.get(), digest.data(), &length) != 1)
    throw std::runtime_error("SHA-256 computation failed in libcrypto");
  out.sha256 = to_hex(digest.data(), length);
  return out;
}

}  // namespace hydrocoef
