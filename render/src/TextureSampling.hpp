#pragma once

#include "penumbra/rhi/Device.hpp"
#include "penumbra/scene/TextureImage.hpp"

#include <optional>
#include <string>

namespace penumbra::render {

// The anisotropy textures are sampled with: FrameDesc::maxAnisotropy clamped to the device's limit, and the
// note that says so when the device gives less than was asked for (1 where it has no anisotropic filtering).
struct AnisotropyChoice {
    float value = 1.0f;
    std::optional<std::string> note;
};
// Throws rhi::Error, naming the field, for a request below 1 (or NaN).
AnisotropyChoice chooseAnisotropy(float requested, const rhi::Capabilities& caps);

// A scene texture's sampler in RHI terms. Anisotropy applies to trilinear samplers only (glTF's
// LINEAR_MIPMAP_LINEAR and the default), so a file that asks for nearest texels or no mip levels gets them.
rhi::SamplerDesc samplerDesc(const scene::TextureSampler& sampler, float anisotropy, const std::string& name);

// Level count for a scene texture: the full chain where its sampler reads mip levels, else 1.
std::uint32_t mipLevelsFor(const scene::TextureImage& image);

} // namespace penumbra::render
