#include "png_writer.hpp"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

namespace sph::render {

namespace {

// libpng reports errors by longjmp; everything with a destructor stays outside that frame.
bool writeRows(std::FILE* out, int width, int height, const std::vector<std::uint8_t>& rgb,
               std::string& error) {
  png_structp png = png_create_write_struct(
      PNG_LIBPNG_VER_STRING, &error,
      [](png_structp p, png_const_charp message) {
        *static_cast<std::string*>(png_get_error_ptr(p)) = message;
        png_longjmp(p, 1);
      },
      nullptr);
  if (png == nullptr) {
    error = "out of memory";
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    if (error.empty()) error = "out of memory";
    return false;
  }
  png_init_io(png, out);
  // Level 6 of zlib costs twice level 3's time for 5 % smaller files; pictures of particles
  // compress poorly either way.
  png_set_compression_level(png, 3);
  png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y)
    png_write_row(png, rgb.data() + std::size_t(y) * std::size_t(width) * 3);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

void writePng(const std::filesystem::path& file, int width, int height,
              const std::vector<std::uint8_t>& rgb) {
  if (width < 1 || height < 1 || rgb.size() != std::size_t(width) * std::size_t(height) * 3)
    throw std::invalid_argument(file.string() + ": " + std::to_string(rgb.size()) +
                                " bytes are not a " + std::to_string(width) + "x" +
                                std::to_string(height) + " RGB image");
  std::filesystem::path tmp = file;
  tmp += ".tmp";
  errno = 0;
  std::FILE* out = std::fopen(tmp.c_str(), "wb");
  if (out == nullptr)
    throw std::runtime_error("cannot open '" + tmp.string() + "': " + std::strerror(errno));
  std::string error;
  const bool written = writeRows(out, width, height, rgb, error);
  const bool closed = std::fclose(out) == 0;
  std::error_code ignored;
  if (!written || !closed) {
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error("cannot write '" + file.string() +
                             "': " + (written ? std::strerror(errno) : error.c_str()));
  }
  std::error_code renameError;
  std::filesystem::rename(tmp, file, renameError);
  if (renameError) {
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error("cannot rename onto '" + file.string() +
                             "': " + renameError.message());
  }
}

}  // namespace sph::render
