#include "SkinningPass.hpp"

#include "penumbra/render/FrameResources.hpp"

namespace penumbra::render {

std::string SkinningPass::name() const { return std::string(frame::kSkinningPass); }

bool SkinningPass::setup(FramePassBuilder& builder)
{
    if (skinning_.empty())
        return false;
    builder.write(frame::kPosedVertices, ResourceUse::StorageWrite);
    return true;
}

void SkinningPass::execute(const FramePassContext& context) { skinning_.record(context.commands()); }

} // namespace penumbra::render
