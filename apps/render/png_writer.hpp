// RGB images to PNG files (libpng).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace sph::render {

// `rgb` holds width × height pixels of 3 bytes, top row first. The file appears whole or not at
// all (written aside, then renamed). Throws std::runtime_error naming the file.
void writePng(const std::filesystem::path& file, int width, int height,
              const std::vector<std::uint8_t>& rgb);

}  // namespace sph::render
