#include "penumbra/imageio/ImageFiles.hpp"

#include "penumbra/rhi/AtomicFile.hpp"
#include "penumbra/rhi/Error.hpp"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfOutputFile.h>
#include <algorithm>
#include <cstring>
#include <exception>
#include <fmt/format.h>
#include <memory>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

namespace penumbra::imageio {
namespace {

// The bytes of an EXR being encoded; OpenEXR seeks back to patch the line offset table, hence the position.
class MemoryOutput : public Imf::OStream {
public:
    MemoryOutput() : Imf::OStream("memory") {}

    void write(const char c[], int n) override
    {
        if (position_ + std::size_t(n) > bytes_.size())
            bytes_.resize(position_ + std::size_t(n));
        std::memcpy(bytes_.data() + position_, c, std::size_t(n));
        position_ += std::size_t(n);
    }
    std::uint64_t tellp() override { return position_; }
    void seekp(std::uint64_t position) override { position_ = position; }

    std::string take() { return std::move(bytes_); }

private:
    std::string bytes_;
    std::size_t position_ = 0;
};

// One interleaved float slice per channel, with the data window's origin at `origin`.
Imf::FrameBuffer frameBuffer(const FloatImage& image, float* values, int originX, int originY)
{
    const std::size_t pixelStride = sizeof(float) * image.channels.size();
    const std::size_t rowStride = pixelStride * image.width;
    char* origin = reinterpret_cast<char*>(values) - std::ptrdiff_t(originX) * std::ptrdiff_t(pixelStride) -
                   std::ptrdiff_t(originY) * std::ptrdiff_t(rowStride);
    Imf::FrameBuffer buffer;
    for (std::size_t c = 0; c < image.channels.size(); ++c)
        buffer.insert(image.channels[c], Imf::Slice(Imf::FLOAT, origin + c * sizeof(float), pixelStride, rowStride));
    return buffer;
}

// An encoding failure reported under the path it was meant for, like writeFileAtomically's own failures.
template <typename Encode>
void writeEncoded(const std::filesystem::path& path, Encode encode)
{
    std::string encoded;
    try {
        encoded = encode();
    } catch (const rhi::Error& e) {
        throw rhi::Error(fmt::format("cannot write {}: {}", path.string(), e.what()));
    }
    rhi::writeFileAtomically(path, encoded);
}

// What `read` returns, with what OpenEXR throws turned into an rhi::Error naming `path` (ours pass as they are).
template <class Read>
FloatImage readingExr(const std::filesystem::path& path, Read read)
{
    try {
        return read();
    } catch (const rhi::Error&) {
        throw;
    } catch (const std::exception& e) {
        throw rhi::Error(fmt::format("{}: cannot read the EXR: {}", path.string(), e.what()));
    }
}

} // namespace

std::optional<std::size_t> FloatImage::channelIndex(std::string_view name) const
{
    const auto found = std::find(channels.begin(), channels.end(), name);
    if (found == channels.end())
        return std::nullopt;
    return std::size_t(found - channels.begin());
}

std::string encodePng(const rhi::Image& image)
{
    if (image.format != rhi::Format::RGBA8)
        throw rhi::Error(fmt::format("PNG needs RGBA8, the image is {}", rhi::formatName(image.format)));
    std::string bytes;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
    };
    if (!stbi_write_png_to_func(append, &bytes, int(image.width), int(image.height), 4, image.bytes.data(),
                                int(image.width * 4)))
        throw rhi::Error(fmt::format("cannot encode a {}x{} PNG", image.width, image.height));
    return bytes;
}

rhi::Image readPng(const std::filesystem::path& path)
{
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load(path.c_str(), &width, &height, &channels, 4),
                                                           stbi_image_free);
    if (!pixels)
        throw rhi::Error(fmt::format("{}: cannot read the PNG: {}", path.string(), stbi_failure_reason()));
    rhi::Image image{std::uint32_t(width), std::uint32_t(height), rhi::Format::RGBA8, {}};
    const auto* first = reinterpret_cast<const std::byte*>(pixels.get());
    image.bytes.assign(first, first + std::size_t(width) * std::size_t(height) * 4);
    return image;
}

FloatImage readHdr(const std::filesystem::path& path)
{
    if (!stbi_is_hdr(path.c_str()))
        throw rhi::Error(fmt::format("{}: not a Radiance RGBE (.hdr) picture{}", path.string(),
                                     std::filesystem::exists(path) ? "" : " (no such file)"));
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<float, void (*)(void*)> values(stbi_loadf(path.c_str(), &width, &height, &channels, 3),
                                                         stbi_image_free);
    if (!values)
        throw rhi::Error(fmt::format("{}: cannot read the HDR: {}", path.string(), stbi_failure_reason()));
    FloatImage image{std::uint32_t(width), std::uint32_t(height), {"R", "G", "B"}, {}};
    image.values.assign(values.get(), values.get() + std::size_t(width) * std::size_t(height) * 3);
    return image;
}

FloatImage readExrColor(const std::filesystem::path& path)
{
    return readingExr(path, [&] {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        FloatImage image{std::uint32_t(window.max.x - window.min.x + 1),
                         std::uint32_t(window.max.y - window.min.y + 1),
                         {"R", "G", "B"},
                         {}};
        for (const std::string& name : image.channels)
            if (!file.header().channels().findChannel(name))
                throw rhi::Error(fmt::format("{}: the EXR has no channel '{}'; an environment needs R, G and B",
                                             path.string(), name));
        image.values.resize(std::size_t(image.width) * image.height * 3);
        file.setFrameBuffer(frameBuffer(image, image.values.data(), window.min.x, window.min.y));
        file.readPixels(window.min.y, window.max.y);
        return image;
    });
}

void writePngFile(const std::filesystem::path& path, const rhi::Image& image)
{
    writeEncoded(path, [&] { return encodePng(image); });
}

std::string encodeExr(const FloatImage& image)
{
    if (image.values.size() != std::size_t(image.width) * image.height * image.channels.size())
        throw rhi::Error(fmt::format("an EXR of {}x{} with {} channels needs {} values, has {}", image.width,
                                     image.height, image.channels.size(),
                                     std::size_t(image.width) * image.height * image.channels.size(),
                                     image.values.size()));
    try {
        Imf::Header header(int(image.width), int(image.height));
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const std::string& name : image.channels)
            header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        MemoryOutput memory;
        Imf::OutputFile file(memory, header);
        // OpenEXR only reads through the slices when writing; the cast keeps one FrameBuffer builder.
        file.setFrameBuffer(frameBuffer(image, const_cast<float*>(image.values.data()), 0, 0));
        file.writePixels(int(image.height));
        return memory.take();
    } catch (const std::exception& e) {
        throw rhi::Error(fmt::format("cannot encode a {}x{} EXR: {}", image.width, image.height, e.what()));
    }
}

FloatImage readExr(const std::filesystem::path& path)
{
    return readingExr(path, [&] {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        FloatImage image;
        image.width = std::uint32_t(window.max.x - window.min.x + 1);
        image.height = std::uint32_t(window.max.y - window.min.y + 1);
        const Imf::ChannelList& channels = file.header().channels();
        for (auto channel = channels.begin(); channel != channels.end(); ++channel) {
            if (channel.channel().type != Imf::FLOAT)
                throw rhi::Error(fmt::format("{}: channel '{}' is not 32-bit float; Penumbra reads float EXR only",
                                             path.string(), channel.name()));
            image.channels.emplace_back(channel.name());
        }
        image.values.resize(std::size_t(image.width) * image.height * image.channels.size());
        file.setFrameBuffer(frameBuffer(image, image.values.data(), window.min.x, window.min.y));
        file.readPixels(window.min.y, window.max.y);
        return image;
    });
}

void writeExrFile(const std::filesystem::path& path, const FloatImage& image)
{
    writeEncoded(path, [&] { return encodeExr(image); });
}

} // namespace penumbra::imageio
