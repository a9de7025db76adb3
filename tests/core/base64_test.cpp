// Base64 decoding: RFC 4648's test vectors, random data encoded by VTK's own
// encoder (an independent implementation), every byte range of a stream,
// and the characters that must be refused.
#include "src/core/base64.hpp"

#include <gtest/gtest.h>
#include <vtkBase64Utilities.h>

#include <random>
#include <string>
#include <vector>

namespace hydrocoef {
namespace {

std::string decode(std::string_view text) {
  std::string out(3 * text.size() / 4 + 3, '\0');
  const Base64Decoded result = decode_base64(text, reinterpret_cast<unsigned char*>(out.data()));
  EXPECT_TRUE(result.ok()) << text << ": bad character at " << result.bad_offset;
  out.resize(result.bytes);
  return out;
}

std::string vtk_encode(const std::vector<unsigned char>& bytes) {
  std::string out(4 * (bytes.size() + 2) / 3 + 4, '\0');
  const unsigned long length =
      vtkBase64Utilities::Encode(bytes.data(), bytes.size(), reinterpret_cast<unsigned char*>(out.data()), 0);
  out.resize(length);
  return out;
}

TEST(Base64, DecodesTheRfc4648TestVectors) {
  EXPECT_EQ(decode(""), "");
  EXPECT_EQ(decode("Zg=="), "f");
  EXPECT_EQ(decode("Zm8="), "fo");
  EXPECT_EQ(decode("Zm9v"), "foo");
  EXPECT_EQ(decode("Zm9vYg=="), "foob");
  EXPECT_EQ(decode("Zm9vYmE="), "fooba");
  EXPECT_EQ(decode("Zm9vYmFy"), "foobar");
}

TEST(Base64, DecodesWhatVtksEncoderWrites) {
  std::mt19937 random(7);
  for (std::size_t size = 0; size < 200; ++size) {
    std::vector<unsigned char> bytes(size);
    for (auto& b : bytes) b = static_cast<unsigned char>(random());
    const std::string text = vtk_encode(bytes);
    ASSERT_EQ(text.size() % 4, 0u);
    std::vector<unsigned char> out(bytes.size() + 3);
    const Base64Decoded result = decode_base64(text, out.data());
    ASSERT_TRUE(result.ok()) << size;
    ASSERT_EQ(result.bytes, size);
    out.resize(size);
    EXPECT_EQ(out, bytes) << size;
  }
}

TEST(Base64, DecodesEveryByteRangeOnItsOwn) {
  std::mt19937 random(11);
  for (const std::size_t size : {1u, 2u, 3u, 4u, 20u, 31u, 32u}) {
    std::vector<unsigned char> bytes(size);
    for (auto& b : bytes) b = static_cast<unsigned char>(random());
    const std::string text = vtk_encode(bytes);
    for (std::size_t first = 0; first <= size; ++first)
      for (std::size_t last = first; last <= size; ++last) {
        std::vector<unsigned char> out(last - first + 1, 0xee);
        ASSERT_TRUE(decode_base64_range(text, first, last, out.data())) << size << " [" << first << ", " << last << ")";
        EXPECT_TRUE(
            std::equal(bytes.begin() + static_cast<long>(first), bytes.begin() + static_cast<long>(last), out.begin()))
            << size << " [" << first << ", " << last << ")";
        EXPECT_EQ(out[last - first], 0xee) << "wrote past the range";
      }
    std::vector<unsigned char> out(size + 4);
    EXPECT_FALSE(decode_base64_range(text, 0, size + 1, out.data())) << "past the end of " << size << " bytes";
  }
}

TEST(Base64, RefusesCharactersOutsideTheAlphabetAndPaddingInside) {
  unsigned char out[16];
  EXPECT_EQ(decode_base64("Zm9v Zm9v", out).bad_offset, 4u) << "blanks are not skipped";
  EXPECT_EQ(decode_base64("Zm9vZ*9v", out).bad_offset, 5u);
  EXPECT_EQ(decode_base64("Zg==Zm9v", out).bad_offset, 2u) << "padding before the last group";
  EXPECT_EQ(decode_base64("Z===", out).bad_offset, 1u);
  EXPECT_EQ(decode_base64("Zm9", out).bad_offset, 0u) << "a group cut short";
  EXPECT_EQ(decode_base64("Zm9vZm9", out).bad_offset, 4u);
  const Base64Decoded stopped = decode_base64("Zm9vYm\x01y", out);
  EXPECT_EQ(stopped.bad_offset, 6u);
  EXPECT_EQ(stopped.bytes, 3u) << "the groups before the bad one are decoded";
  EXPECT_FALSE(decode_base64_range("Zm9vYm*y", 2, 5, out));
  EXPECT_TRUE(decode_base64_range("Zm9vYm*y", 0, 3, out)) << "a range before the bad group";
}

}  // namespace
}  // namespace hydrocoef
