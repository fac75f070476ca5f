#pragma once
// PNG files of rendered frames (stb_image_write / stb_image).
#include <cstdint>
#include <string>
#include <vector>

namespace imasim::render {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // rows from the top
};

// Throws std::runtime_error naming the file when it cannot be written.
void write_png(const std::string& path, const RgbImage& image);
// Throws std::runtime_error naming the file when it is missing or not an image.
RgbImage read_png(const std::string& path);

}  // namespace imasim::render
