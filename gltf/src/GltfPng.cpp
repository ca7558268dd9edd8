#include "GltfPng.hpp"

#include "GltfHugePages.hpp"
#include "GltfImages.hpp"

#include <fmt/format.h>
#include <png.h>

#include <csetjmp>
#include <cstring>
#include <new>
#include <stdexcept>

namespace penumbra::gltf {
namespace {

// What libpng's callbacks share with the decoder. Plain data only: on an error libpng's error function longjmps
// back to the setjmp of readPngHeader or readPngRows (the libpng manual's "Error handling": the function must not
// return), over libpng's frames and these, so no frame it skips may own anything with a destructor.
struct PngSource {
    const std::uint8_t* bytes;
    std::size_t size;
    std::size_t at;
    char message[256];
};

void pngReadBytes(png_structp png, png_bytep out, std::size_t count)
{
    auto* source = static_cast<PngSource*>(png_get_io_ptr(png));
    if (count > source->size - source->at)
        png_error(png, "the picture's data ends early");
    std::memcpy(out, source->bytes + source->at, count);
    source->at += count;
}

[[noreturn]] void pngFail(png_structp png, png_const_charp message)
{
    auto* source = static_cast<PngSource*>(png_get_error_ptr(png));
    std::strncpy(source->message, message ? message : "", sizeof source->message - 1);
    source->message[sizeof source->message - 1] = '\0';
    png_longjmp(png, 1);
}

// Warnings (an ancillary chunk libpng drops, a known incorrect ICC profile) change no texel; libpng's default would
// print them on stderr.
void pngIgnoreWarning(png_structp, png_const_charp) {}

// libpng's read and info structures, destroyed on every path.
struct PngReader {
    png_structp png = nullptr;
    png_infop info = nullptr;
    explicit PngReader(PngSource& source)
    {
        png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &source, pngFail, pngIgnoreWarning);
        if (png)
            info = png_create_info_struct(png);
        if (!png || !info) {
            png_destroy_read_struct(png ? &png : nullptr, nullptr, nullptr);
            throw std::bad_alloc();
        }
        png_set_read_fn(png, &source, pngReadBytes);
    }
    ~PngReader() { png_destroy_read_struct(&png, &info, nullptr); }
    PngReader(const PngReader&) = delete;
    PngReader& operator=(const PngReader&) = delete;
};

// Reads the chunks up to the first IDAT and sets the transformations to RGBA8; false on an error (the source's
// message says which). Sets `width` and `height` from IHDR.
bool readPngHeader(png_structp png, png_infop info, png_uint_32* width, png_uint_32* height)
{
    if (setjmp(png_jmpbuf(png)))
        return false;
    // stb_image, the loader's decoder before libpng, checked neither chunk CRCs nor zlib's Adler-32: a picture it
    // decoded still decodes, to the same texels.
    png_set_crc_action(png, PNG_CRC_QUIET_USE, PNG_CRC_QUIET_USE);
    png_set_option(png, PNG_IGNORE_ADLER32, PNG_OPTION_ON);
    png_read_info(png, info);
    *width = png_get_image_width(png, info);
    *height = png_get_image_height(png, info);
    const int colourType = png_get_color_type(png, info);
    const bool transparency = png_get_valid(png, info, PNG_INFO_tRNS) != 0;
    png_set_expand(png); // palette to RGB, grey of 1, 2 or 4 bits to 8, tRNS to alpha
    png_set_scale_16(png);
    png_set_gray_to_rgb(png);
    if ((colourType & PNG_COLOR_MASK_ALPHA) == 0 && !transparency)
        png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    return true;
}

// Decodes every row (every pass's rows of an interlaced picture, each pass combined into the rows) into `rgba`;
// false on an error.
bool readPngRows(png_structp png, png_infop info, unsigned char* rgba, png_uint_32 width, png_uint_32 height)
{
    if (setjmp(png_jmpbuf(png)))
        return false;
    const int passes = png_get_interlace_type(png, info) == PNG_INTERLACE_ADAM7 ? PNG_INTERLACE_ADAM7_PASSES : 1;
    for (int pass = 0; pass < passes; ++pass)
        for (png_uint_32 y = 0; y < height; ++y)
            png_read_row(png, rgba + std::size_t(y) * width * 4, nullptr);
    return true;
}

} // namespace

PngPicture decodePng(std::span<const std::uint8_t> bytes)
{
    PngSource source{bytes.data(), bytes.size(), 0, {}};
    PngReader reader(source);
    png_uint_32 width = 0, height = 0;
    if (!readPngHeader(reader.png, reader.info, &width, &height))
        throw std::runtime_error(fmt::format("does not decode: libpng: {}", source.message));
    if (width > kMaxImageSide || height > kMaxImageSide || std::uint64_t(width) * height > kMaxImageTexels)
        throw std::runtime_error(fmt::format("is {}x{} texels, over the limits of {} a side and {} texels", width,
                                             height, kMaxImageSide, kMaxImageTexels));
    if (png_get_rowbytes(reader.png, reader.info) != std::size_t(width) * 4)
        throw std::runtime_error(fmt::format("does not decode: libpng gives {} bytes a row, not RGBA8's {}",
                                             png_get_rowbytes(reader.png, reader.info), std::size_t(width) * 4));
    PngPicture picture{width, height, hugePageBytes(std::size_t(width) * height * 4)};
    if (!readPngRows(reader.png, reader.info, picture.rgba.data(), width, height))
        throw std::runtime_error(fmt::format("does not decode: libpng: {}", source.message));
    return picture;
}

} // namespace penumbra::gltf
