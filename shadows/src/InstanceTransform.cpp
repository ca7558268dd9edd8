#include "penumbra/shadows/InstanceTransform.hpp"

#include <algorithm>
#include <cstddef>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace penumbra::shadows {

InstanceTransform instanceTransform(const glm::mat4& model)
{
    const glm::mat3 upper(model);
    const glm::mat3 normal = glm::transpose(glm::inverse(upper));
    const float handedness = glm::determinant(upper) < 0.0f ? -1.0f : 1.0f;
    return {model, {glm::vec4(normal[0], handedness), glm::vec4(normal[1], 0.0f), glm::vec4(normal[2], 0.0f)}};
}

void addInstanceAttributes(rhi::VertexLayout& layout, std::uint32_t slot)
{
    layout.buffers.resize(std::max<std::size_t>(layout.buffers.size(), slot + 1));
    layout.buffers[slot] = {sizeof(InstanceTransform), true};
    for (std::uint32_t column = 0; column < 4; ++column)
        layout.attributes.push_back(
            {kInstanceFirstLocation + column, rhi::VertexFormat::Float4,
             static_cast<std::uint32_t>(offsetof(InstanceTransform, model) + column * sizeof(glm::vec4)), slot});
    for (std::uint32_t column = 0; column < 3; ++column)
        layout.attributes.push_back(
            {kInstanceFirstLocation + 4 + column, rhi::VertexFormat::Float4,
             static_cast<std::uint32_t>(offsetof(InstanceTransform, normalColumns) + column * sizeof(glm::vec4)),
             slot});
}

} // namespace penumbra::shadows
