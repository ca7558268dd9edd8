#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <functional>
#include <span>
#include <string>

namespace penumbra::gltf {

// The largest picture a glTF image may decode to, checked from its header before any pixel is
// decoded: 16384 texels a side (the largest 2D texture Vulkan and OpenGL implementations commonly
// allow) and 2^26 texels in all (256 MiB as RGBA8).
inline constexpr std::uint32_t kMaxImageSide = 16384;
inline constexpr std::uint64_t kMaxImageTexels = std::uint64_t(1) << 26;

// Decodes a PNG (libpng, decodePng) or JPEG (stb_image) image (glTF 2.0, section 3.8.1: the two image formats core
// glTF allows) into `image` as RGBA8 (width, height, component 4, bits 8): grey spread over RGB, a missing alpha
// opaque, 16-bit channels rounded to nearest.
// Returns what is wrong, or "" on success: an unknown or truncated format, a picture over the limits,
// pixel data that does not decode.
std::string decodeImage(std::span<const std::uint8_t> bytes, tinygltf::Image& image);

// tinygltf's image-loading callback (TinyGLTF::SetImageLoader): checks the format and the header's size, and sets
// image.as_is for decodeStashedImages to decode them all at once, keeping a copy of the encoded bytes in image.image
// unless they lie in a buffer view (image.bufferView), which the model keeps. A failure
// is also written to `user`, a std::string, as "/images/<index>: the picture <what is wrong>".
bool stashImageData(tinygltf::Image* image, int index, std::string* error, std::string* warning, int requestedWidth,
                    int requestedHeight, const unsigned char* bytes, int size, void* user);

// Decodes every image that stashImageData kept (decodeImage), one per hardware thread at a time; progress(done, total)
// after each, on one thread at a time. Returns the first failure by image index, "/images/<index>: the picture <what
// is wrong>", or "".
std::string decodeStashedImages(tinygltf::Model& model, const std::function<void(std::size_t, std::size_t)>& progress);

} // namespace penumbra::gltf
