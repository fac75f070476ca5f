#include "render/image_file.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <memory>
#include <stdexcept>

namespace imasim::render {

void write_png(const std::string& path, const RgbImage& image) {
  if (image.width < 1 || image.height < 1 ||
      image.rgb.size() != std::size_t(image.width) * std::size_t(image.height) * 3)
    throw std::invalid_argument("write_png: the image's size does not match its pixels");
  if (!stbi_write_png(path.c_str(), image.width, image.height, 3, image.rgb.data(),
                      image.width * 3))
    throw std::runtime_error("cannot write the image " + path);
}

RgbImage read_png(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> data(
      stbi_load(path.c_str(), &w, &h, &channels, 3), stbi_image_free);
  if (!data)
    throw std::runtime_error("cannot read the image " + path + ": " + stbi_failure_reason());
  RgbImage image;
  image.width = w, image.height = h;
  image.rgb.assign(data.get(), data.get() + std::size_t(w) * std::size_t(h) * 3);
  return image;
}

}  // namespace imasim::render
