// libpng in memory: the full write API (for the compression level and filter), the simplified read API.
//
// libpng reports errors by longjmp to the setjmp in the function that called it. Only trivially
// destructible objects live between those points in encode_into(), so the jump skips no destructor.
#include "output/png_codec.hpp"

#include <csetjmp>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <png.h>

namespace output {
namespace {

void append_to_string(png_structp png, png_bytep data, png_size_t length) {
  auto* bytes = static_cast<std::string*>(png_get_io_ptr(png));
  bytes->append(reinterpret_cast<const char*>(data), length);
}

void flush_nothing(png_structp) {}

// Writes `image` as PNG into `bytes`; returns false if libpng failed (after cleaning up).
bool encode_into(const softbody::Image& image, png_bytep* rows, std::string* bytes) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, bytes, append_to_string, flush_nothing);
  png_set_compression_level(png, 1);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
  png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

std::string encode_png(const softbody::Image& image) {
  if (image.width <= 0 || image.height <= 0 || image.rgb.size() != image.row_bytes() * image.height) {
    throw std::invalid_argument("encode_png: image size and pixel buffer disagree");
  }
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
  for (int y = 0; y < image.height; ++y) rows[y] = const_cast<png_bytep>(image.pixel(0, y));
  std::string bytes;
  bytes.reserve(image.rgb.size() / 8);
  if (!encode_into(image, rows.data(), &bytes)) throw std::runtime_error("libpng failed to encode a frame");
  return bytes;
}

softbody::Image decode_png(std::string_view bytes, const std::string& name) {
  png_image decoder{};
  decoder.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&decoder, bytes.data(), bytes.size())) {
    throw std::runtime_error(name + ": not a PNG (" + decoder.message + ")");
  }
  decoder.format = PNG_FORMAT_RGB;
  softbody::Image image(static_cast<int>(decoder.width), static_cast<int>(decoder.height));
  if (!png_image_finish_read(&decoder, nullptr, image.rgb.data(), static_cast<png_int_32>(image.row_bytes()),
                             nullptr)) {
    const std::string message = decoder.message;
    png_image_free(&decoder);
    throw std::runtime_error(name + ": cannot decode the PNG (" + message + ")");
  }
  return image;
}

softbody::Image read_png(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  std::stringstream bytes;
  bytes << in.rdbuf();
  return decode_png(bytes.str(), path.string());
}

}  // namespace output
