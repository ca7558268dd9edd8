#include "GltfImages.hpp"

#include "GltfHugePages.hpp"
#include "GltfPng.hpp"

#include <fmt/format.h>
#include <stb/stb_image.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

namespace penumbra::gltf {
namespace {

// The signatures of PNG (RFC 2083, section 3.1) and JPEG (ITU T.81, annex B: an SOI marker and the
// next marker's first byte).
constexpr std::array<std::uint8_t, 8> kPng{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr std::array<std::uint8_t, 3> kJpeg{0xff, 0xd8, 0xff};

template <std::size_t N>
bool startsWith(std::span<const std::uint8_t> bytes, const std::array<std::uint8_t, N>& signature)
{
    return bytes.size() >= N && std::equal(signature.begin(), signature.end(), bytes.begin());
}

std::uint32_t bigEndian(std::span<const std::uint8_t> bytes, std::size_t at, std::size_t size)
{
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < size; ++i)
        value = value << 8 | bytes[at + i];
    return value;
}

struct Dimensions {
    std::uint32_t width = 0, height = 0;
};

// The picture's size from its header, before any decoder sees it: PNG's IHDR chunk, first after the signature
// (RFC 2083, section 4.1.1); JPEG's first start-of-frame marker SOF0 to SOF15 but DHT, JPG and DAC (ITU T.81,
// B.2.2). Nothing for a header cut short.
std::optional<Dimensions> headerDimensions(std::span<const std::uint8_t> bytes)
{
    if (startsWith(bytes, kPng))
        return bytes.size() >= 24 ? std::optional(Dimensions{bigEndian(bytes, 16, 4), bigEndian(bytes, 20, 4)})
                                  : std::nullopt;
    for (std::size_t at = 2; at + 4 <= bytes.size();) {
        if (bytes[at] != 0xff)
            return std::nullopt;
        const std::uint8_t marker = bytes[at + 1];
        const std::uint32_t length = bigEndian(bytes, at + 2, 2);
        if (marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc)
            return at + 9 <= bytes.size()
                       ? std::optional(Dimensions{bigEndian(bytes, at + 7, 2), bigEndian(bytes, at + 5, 2)})
                       : std::nullopt;
        at += 2 + length;
    }
    return std::nullopt;
}

struct StbFree {
    void operator()(void* pixels) const { stbi_image_free(pixels); }
};

// Decoded JPEG texels of 1 to 4 channels as RGBA8, as the scene keeps them: grey (and grey-alpha) spread over RGB,
// a missing alpha opaque. Done here, on the decoding threads, rather than later on one.
std::vector<unsigned char> rgba8Of(const std::uint8_t* pixels, std::size_t texels, int channels)
{
    std::vector<unsigned char> rgba = hugePageBytes(texels * 4);
    if (channels == 4) {
        std::copy(pixels, pixels + texels * 4, rgba.begin());
        return rgba;
    }
    const auto count = std::size_t(channels);
    for (std::size_t t = 0; t < texels; ++t) {
        const std::uint8_t* texel = pixels + t * count;
        unsigned char* out = rgba.data() + t * 4;
        const bool grey = channels <= 2;
        out[0] = texel[0];
        out[1] = texel[grey ? 0 : 1];
        out[2] = texel[grey ? 0 : 2];
        out[3] = channels == 2 || channels == 4 ? texel[count - 1] : 255;
    }
    return rgba;
}

} // namespace

std::string decodeImage(std::span<const std::uint8_t> bytes, tinygltf::Image& image)
{
    if (!startsWith(bytes, kPng) && !startsWith(bytes, kJpeg))
        return "is neither a PNG nor a JPEG picture";
    if (bytes.size() > std::size_t(std::numeric_limits<int>::max()))
        return fmt::format("has {} bytes, more than a picture may have", bytes.size());
    if (const std::optional<Dimensions> header = headerDimensions(bytes);
        header && (header->width > kMaxImageSide || header->height > kMaxImageSide ||
                   std::uint64_t(header->width) * header->height > kMaxImageTexels))
        return fmt::format("is {}x{} texels, over the limits of {} a side and {} texels", header->width, header->height,
                           kMaxImageSide, kMaxImageTexels);
    image.component = 4;
    image.bits = 8;
    image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    if (startsWith(bytes, kPng)) {
        try {
            PngPicture picture = decodePng(bytes);
            image.width = int(picture.width);
            image.height = int(picture.height);
            image.image = std::move(picture.rgba);
        } catch (const std::runtime_error& failure) {
            return failure.what();
        }
        return {};
    }
    const int size = int(bytes.size());
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(bytes.data(), size, &width, &height, &channels))
        return fmt::format("has an unreadable header: {}", stbi_failure_reason());
    if (width <= 0 || height <= 0 || std::uint32_t(width) > kMaxImageSide || std::uint32_t(height) > kMaxImageSide ||
        std::uint64_t(width) * std::uint64_t(height) > kMaxImageTexels)
        return fmt::format("is {}x{} texels, over the limits of {} a side and {} texels", width, height, kMaxImageSide,
                           kMaxImageTexels);
    image.width = width;
    image.height = height;
    int decodedWidth = 0, decodedHeight = 0, decodedChannels = 0;
    std::unique_ptr<stbi_uc, StbFree> pixels(
        stbi_load_from_memory(bytes.data(), size, &decodedWidth, &decodedHeight, &decodedChannels, 0));
    if (!pixels)
        return fmt::format("does not decode: {}", stbi_failure_reason());
    if (decodedWidth != width || decodedHeight != height || decodedChannels < 1 || decodedChannels > 4)
        return fmt::format("decoded to {}x{} texels of {} channels, its header says {}x{}", decodedWidth, decodedHeight,
                           decodedChannels, width, height);
    image.image = rgba8Of(pixels.get(), std::size_t(width) * std::size_t(height), decodedChannels);
    return {};
}

bool stashImageData(tinygltf::Image* image, int index, std::string* error, std::string*, int, int,
                    const unsigned char* bytes, int size, void* user)
{
    const std::span<const std::uint8_t> encoded(bytes, size > 0 ? std::size_t(size) : 0u);
    const std::optional<Dimensions> header = headerDimensions(encoded);
    std::string why;
    if (!startsWith(encoded, kPng) && !startsWith(encoded, kJpeg))
        why = "is neither a PNG nor a JPEG picture";
    else if (header && (header->width > kMaxImageSide || header->height > kMaxImageSide ||
                        std::uint64_t(header->width) * header->height > kMaxImageTexels))
        why = fmt::format("is {}x{} texels, over the limits of {} a side and {} texels", header->width, header->height,
                          kMaxImageSide, kMaxImageTexels);
    if (why.empty()) {
        // A buffer view's bytes stay in the model's buffer, which outlives the decoding: no copy of them is kept.
        if (image->bufferView < 0)
            image->image.assign(encoded.begin(), encoded.end());
        image->as_is = true;
        return true;
    }
    const std::string failure = fmt::format("/images/{}: the picture {}", index, why);
    if (user)
        *static_cast<std::string*>(user) = failure;
    if (error)
        *error += failure;
    return false;
}

namespace {

// The bytes of a buffer view, whose range checkLayout has checked.
std::span<const std::uint8_t> bufferViewBytes(const tinygltf::Model& model, int index)
{
    const tinygltf::BufferView& view = model.bufferViews.at(std::size_t(index));
    const std::vector<unsigned char>& buffer = model.buffers.at(std::size_t(view.buffer)).data;
    return std::span(buffer).subspan(view.byteOffset, view.byteLength);
}

} // namespace

std::string decodeStashedImages(tinygltf::Model& model, const std::function<void(std::size_t, std::size_t)>& progress)
{
    std::vector<std::size_t> stashed;
    for (std::size_t i = 0; i < model.images.size(); ++i)
        if (model.images[i].as_is)
            stashed.push_back(i);
    std::vector<std::string> failures(stashed.size());
    std::atomic<std::size_t> next{0}, done{0};
    std::mutex reporting;
    const auto work = [&] {
        for (std::size_t k = next++; k < stashed.size(); k = next++) {
            tinygltf::Image& image = model.images[stashed[k]];
            const std::vector<unsigned char> kept = std::move(image.image);
            image.image.clear();
            image.as_is = false;
            failures[k] = decodeImage(kept.empty() ? bufferViewBytes(model, image.bufferView)
                                                   : std::span<const std::uint8_t>(kept),
                                      image);
            const std::size_t finished = ++done;
            if (progress) {
                const std::lock_guard lock(reporting);
                progress(finished, stashed.size());
            }
        }
    };
    // Each picture decodes on its own (libpng's state is per picture, stb_image keeps its failure reason per thread),
    // so the pictures do not depend on the thread count.
    const std::size_t helpers = std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()) - 1,
                                                      stashed.size() > 0 ? stashed.size() - 1 : 0);
    {
        std::vector<std::jthread> threads;
        for (std::size_t i = 0; i < helpers; ++i)
            threads.emplace_back(work);
        work();
    }
    for (std::size_t k = 0; k < stashed.size(); ++k)
        if (!failures[k].empty())
            return fmt::format("/images/{}: the picture {}", stashed[k], failures[k]);
    return {};
}

} // namespace penumbra::gltf
