#pragma once

#include "penumbra/rhi/Device.hpp"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <vector>

namespace penumbra::testing {

// Samples a texture through a real draw: every pixel of a width x height RGBA32F target outputs
// textureLod(texture, origin + step * pixel, lod), pixel counted from the top-left. The LOD is explicit so a
// test knows which levels the sampler's clamps and filters must pick.
class TextureProbe {
public:
    explicit TextureProbe(rhi::Device& device);

    struct Request {
        glm::vec2 origin{0.0f};
        glm::vec2 step{0.0f};
        float lod = 0.0f;
        std::uint32_t width = 1;
        std::uint32_t height = 1;
    };
    // Row-major, row 0 first.
    std::vector<glm::vec4> sample(const rhi::Texture& texture, const rhi::Sampler& sampler, const Request& request);

private:
    rhi::Device& device_;
    std::unique_ptr<rhi::Shader> vertex_, fragment_;
    std::unique_ptr<rhi::Pipeline> pipeline_;
    std::unique_ptr<rhi::Buffer> uniforms_;
};

} // namespace penumbra::testing
