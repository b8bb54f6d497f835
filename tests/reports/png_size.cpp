#include "tests/reports/png_size.hpp"

#include <array>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace ccm::test {
namespace {

std::uint32_t big_endian_u32(const std::vector<unsigned char>& b, std::size_t at) {
  return (std::uint32_t(b[at]) << 24) | (std::uint32_t(b[at + 1]) << 16) |
         (std::uint32_t(b[at + 2]) << 8) | std::uint32_t(b[at + 3]);
}

}  // namespace

std::optional<PngSummary> summarise_png(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in), {}};
  constexpr std::array<unsigned char, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 8 || !std::equal(kSignature.begin(), kSignature.end(), bytes.begin()))
    return std::nullopt;
  PngSummary png;
  std::size_t at = 8;
  while (at + 12 <= bytes.size()) {  // length, type, data, CRC
    const std::uint32_t length = big_endian_u32(bytes, at);
    const std::string type(bytes.begin() + long(at) + 4, bytes.begin() + long(at) + 8);
    if (at + 12 + length > bytes.size()) return std::nullopt;
    if (type == "IHDR" && length >= 8) {
      png.width = big_endian_u32(bytes, at + 8);
      png.height = big_endian_u32(bytes, at + 12);
    }
    if (type == "IDAT") png.idat_bytes += length;
    if (type == "IEND") return png;
    at += 12 + length;
  }
  return std::nullopt;
}

}  // namespace ccm::test
