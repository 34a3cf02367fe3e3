#include "io/png_writer.h"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>

#include "io/atomic_file.h"

namespace f2 {

namespace {
void pngError(png_structp png, png_const_charp message) {
    auto* error = static_cast<std::string*>(png_get_error_ptr(png));
    *error = message;
    png_longjmp(png, 1);
}
void pngWarning(png_structp, png_const_charp) {}

// Kept out of functions that call setjmp, so no C++ object with a destructor
// lives across the longjmp.
bool writeRows(std::FILE* file, const Image& image, std::string& error) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, pngError, pngWarning);
    if (!png) return false;
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_level(png, 3);  // fast: frames are written by the hundred
    png_write_info(png, info);
    for (int y = 0; y < image.height; ++y)
        png_write_row(png, reinterpret_cast<png_const_bytep>(&image.pixels[std::size_t(y) * image.width]));
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return true;
}
}  // namespace

bool writePng(const Image& image, const std::string& path, std::string& error) {
    if (image.width <= 0 || image.height <= 0) {
        error = "cannot write an empty image";
        return false;
    }
    AtomicFile file(path);
    if (!file.ok()) {
        error = file.error();
        return false;
    }
    if (!writeRows(file.handle(), image, error)) {
        // libpng says only "Write Error"; the system says why (a full disk, /dev/full).
        const int cause = errno;
        error = "cannot write '" + path + "': " +
                (std::ferror(file.handle()) && cause != 0 ? std::string(std::strerror(cause)) : error);
        return false;
    }
    if (!file.commit()) {
        error = file.error();
        return false;
    }
    return true;
}

bool writePng(const Image& image, std::FILE* stream, std::string& error) {
    if (image.width <= 0 || image.height <= 0) {
        error = "cannot write an empty image";
        return false;
    }
    errno = 0;
    if (!writeRows(stream, image, error) || std::fflush(stream) != 0 || std::ferror(stream)) {
        const int cause = errno;  // why the system refused (a full disk, /dev/full), if it did
        if (std::ferror(stream) && cause != 0) error = std::strerror(cause);
        error = "cannot write the PNG to the stream" + (error.empty() ? std::string() : ": " + error);
        return false;
    }
    return true;
}

bool readPng(const std::string& path, Image& image, std::string& error) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&png, path.c_str())) {
        error = "cannot read '" + path + "': " + png.message;
        return false;
    }
    png.format = PNG_FORMAT_RGB;
    image.resize(int(png.width), int(png.height));
    if (!png_image_finish_read(&png, nullptr, image.pixels.data(), 0, nullptr)) {
        error = "cannot read '" + path + "': " + png.message;
        png_image_free(&png);
        return false;
    }
    return true;
}

}  // namespace f2
