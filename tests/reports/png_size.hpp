// Minimal PNG reading for screenshot checks (no decoder in the dependencies): the image size
// from IHDR and the total compressed size of the IDAT chunks. A page of uniform colour
// compresses to almost nothing, so the IDAT size is a proxy for how much is drawn.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>

namespace ccm::test {

struct PngSummary {
  std::uint32_t width = 0, height = 0;
  std::uint64_t idat_bytes = 0;
};

// Empty when the file is not a well-formed PNG (signature, chunk lengths within the file).
std::optional<PngSummary> summarise_png(const std::filesystem::path& file);

}  // namespace ccm::test
