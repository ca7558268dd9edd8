#include "GltfPng.hpp"

#include <sys/mman.h>
#include <zlib.h>

#include <cstdlib>
#include <cstring>
#include <string_view>

namespace penumbra::gltf {
namespace {

std::uint32_t pngBigEndian(const std::uint8_t* bytes)
{
    return std::uint32_t(bytes[0]) << 24 | std::uint32_t(bytes[1]) << 16 | std::uint32_t(bytes[2]) << 8 | bytes[3];
}

// The Paeth predictor (W3C PNG, section 9.4): whichever of left, above and upper left is nearest a + b - c.
std::uint8_t paethPredictor(int a, int b, int c)
{
    const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    return std::uint8_t(pa <= pb && pa <= pc ? a : pb <= pc ? b : c);
}

// Undoes a row's filter (section 9.2) in place; `above` is the previous row, zeros for the first.
bool unfilterPngRow(std::uint8_t filter, std::uint8_t* row, const std::uint8_t* above, std::size_t size,
                    std::size_t bpp)
{
    switch (filter) {
    case 0:
        return true;
    case 1:
        for (std::size_t i = bpp; i < size; ++i)
            row[i] = std::uint8_t(row[i] + row[i - bpp]);
        return true;
    case 2:
        for (std::size_t i = 0; i < size; ++i)
            row[i] = std::uint8_t(row[i] + above[i]);
        return true;
    case 3:
        for (std::size_t i = 0; i < size; ++i)
            row[i] = std::uint8_t(row[i] + ((i >= bpp ? row[i - bpp] : 0) + above[i]) / 2);
        return true;
    case 4:
        for (std::size_t i = 0; i < size; ++i)
            row[i] = std::uint8_t(row[i] + (i >= bpp ? paethPredictor(row[i - bpp], above[i], above[i - bpp])
                                                     : paethPredictor(0, above[i], 0)));
        return true;
    default:
        return false;
    }
}

// `size` zeroed bytes whose pages the kernel may back with transparent huge pages (madvise(2), MADV_HUGEPAGE, for
// systems that leave them to madvise): a fresh 16 MiB picture otherwise takes 4096 page faults, and page faults were a
// third of loading a dozen 2048 x 2048 textures on a virtual machine. A hint: where it fails, nothing changes.
std::vector<unsigned char> freshPicture(std::size_t size)
{
    std::vector<unsigned char> bytes;
    bytes.reserve(size);
    constexpr std::uintptr_t kHugePage = std::uintptr_t(2) << 20;
    const auto first = reinterpret_cast<std::uintptr_t>(bytes.data());
    const std::uintptr_t begin = (first + kHugePage - 1) & ~(kHugePage - 1), end = (first + size) & ~(kHugePage - 1);
    if (end > begin)
        madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
    bytes.resize(size);
    return bytes;
}

// zlib's inflate state, ended on every path.
struct PngInflater {
    z_stream stream{};
    bool open = false;
    PngInflater() { open = inflateInit(&stream) == Z_OK; }
    ~PngInflater()
    {
        if (open)
            inflateEnd(&stream);
    }
    PngInflater(const PngInflater&) = delete;
    PngInflater& operator=(const PngInflater&) = delete;
};

} // namespace

std::optional<std::vector<unsigned char>> decodeTruecolourPng(std::span<const std::uint8_t> bytes)
{
    // The signature, then IHDR first (section 11.2.2): width, height, depth, colour type, compression, filter,
    // interlace.
    if (bytes.size() < 33 || std::string_view(reinterpret_cast<const char*>(bytes.data()) + 12, 4) != "IHDR" ||
        pngBigEndian(bytes.data() + 8) != 13)
        return std::nullopt;
    const std::uint8_t* header = bytes.data() + 16;
    const std::uint32_t width = pngBigEndian(header), height = pngBigEndian(header + 4);
    const std::uint8_t depth = header[8], colourType = header[9];
    if (width == 0 || height == 0 || depth != 8 || (colourType != 2 && colourType != 6) || header[10] != 0 ||
        header[11] != 0 || header[12] != 0)
        return std::nullopt;
    const std::size_t bpp = colourType == 6 ? 4 : 3, rowSize = std::size_t(width) * bpp;
    std::vector<unsigned char> rgba = freshPicture(std::size_t(width) * height * 4);
    std::vector<std::uint8_t> rows(2 * (rowSize + 1), 0); // this row and the one above, each after its filter byte
    PngInflater inflater;
    if (!inflater.open)
        return std::nullopt;
    z_stream& stream = inflater.stream;
    std::uint32_t y = 0;
    std::size_t filled = 0; // bytes of the current row (filter byte first) inflated so far
    bool ended = false;
    // Inflates the input the stream holds into rows, until it needs more; false where the data breaks the picture.
    const auto inflateRows = [&] {
        for (;;) {
            std::uint8_t past = 0; // where data past the last row would go
            std::uint8_t* row = rows.data() + (y % 2) * (rowSize + 1);
            stream.next_out = y < height ? row + filled : &past;
            stream.avail_out = y < height ? uInt(rowSize + 1 - filled) : 1u;
            const int result = inflate(&stream, Z_NO_FLUSH);
            if (result == Z_BUF_ERROR)
                return true; // no progress without more input
            if (result != Z_OK && result != Z_STREAM_END)
                return false;
            ended = result == Z_STREAM_END;
            if (y == height)
                return stream.avail_out == 1 && (ended || stream.avail_in == 0);
            filled = rowSize + 1 - stream.avail_out;
            if (filled == rowSize + 1) {
                const std::uint8_t* above = rows.data() + ((y + 1) % 2) * (rowSize + 1);
                if (!unfilterPngRow(row[0], row + 1, above + 1, rowSize, bpp))
                    return false;
                unsigned char* out = rgba.data() + std::size_t(y) * width * 4;
                for (std::size_t x = 0; x < width; ++x) {
                    std::memcpy(out + x * 4, row + 1 + x * bpp, bpp);
                    if (bpp == 3)
                        out[x * 4 + 3] = 255;
                }
                filled = 0;
                ++y;
            } else if (!ended) {
                return true; // the input ran out inside a row
            }
            if (ended)
                return true;
        }
    };
    for (std::size_t at = 33; at + 12 <= bytes.size();) {
        const std::uint32_t length = pngBigEndian(bytes.data() + at);
        const std::string_view type(reinterpret_cast<const char*>(bytes.data()) + at + 4, 4);
        if (length > bytes.size() - at - 12)
            return std::nullopt;
        const std::uint8_t* data = bytes.data() + at + 8;
        at += 12 + std::size_t(length);
        if (type == "IEND")
            break;
        if (type != "IDAT") {
            // Ancillary chunks (lower-case first letter) other than transparency change no texel here.
            if (type == "tRNS" || type == "CgBI" || (type[0] >= 'A' && type[0] <= 'Z'))
                return std::nullopt;
            continue;
        }
        if (ended)
            return std::nullopt;
        stream.next_in = const_cast<Bytef*>(data);
        stream.avail_in = length;
        if (!inflateRows())
            return std::nullopt;
    }
    if (!ended || y != height)
        return std::nullopt;
    return rgba;
}

} // namespace penumbra::gltf
