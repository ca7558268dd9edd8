#include "penumbra/shadows/InstanceTransform.hpp"

#include <algorithm>
#include <cstddef>
#include <glm/matrix.hpp>

namespace penumbra::shadows {

InstanceTransform instanceTransform(const glm::mat4& model)
{
    const glm::mat4 rows = glm::transpose(model);
    return {{rows[0], rows[1], rows[2]}};
}

void addInstanceAttributes(rhi::VertexLayout& layout, std::uint32_t slot)
{
    layout.buffers.resize(std::max<std::size_t>(layout.buffers.size(), slot + 1));
    layout.buffers[slot] = {sizeof(InstanceTransform), true};
    for (std::uint32_t row = 0; row < 3; ++row)
        layout.attributes.push_back(
            {kInstanceFirstLocation + row, rhi::VertexFormat::Float4,
             static_cast<std::uint32_t>(offsetof(InstanceTransform, rows) + row * sizeof(glm::vec4)), slot});
}

} // namespace penumbra::shadows
