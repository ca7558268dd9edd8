#include "ImGuiRenderer.hpp"

#include "penumbra/shaders/ShaderBlock.hpp"
#include "penumbra/shaders/ShaderLibrary.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <glm/vec4.hpp>
#include <imgui.h>

namespace penumbra::viewer {
namespace {

constexpr std::uint32_t kFrameBinding = 0;
constexpr std::uint32_t kTextureBinding = 1;

// imgui.vert's uniform block ImGuiFrame (std140): window pixels to NDC, xy the scale, zw the offset; y is negative
// because canonical NDC y points up.
struct ImGuiFrameUniforms {
    glm::vec4 pixelToNdc{0.0f};
};
constexpr std::array kImGuiFrameFields{PENUMBRA_SHADER_FIELD(ImGuiFrameUniforms, pixelToNdc)};
constexpr shaders::ShaderStruct kImGuiFrameBlock{"ImGuiFrame", sizeof(ImGuiFrameUniforms), kImGuiFrameFields};
static_assert(shaders::matchesLayout(kImGuiFrameBlock, shaders::BlockLayout::Std140));

rhi::ShaderSource imguiVertexShader()
{
    rhi::ShaderSource source = shaders::load("imgui.vert");
    source.includes.push_back(
        {"imgui_blocks.glsl", shaders::uniformBlockGlsl(kImGuiFrameBlock, kFrameBinding, "frame")});
    return source;
}

static_assert(sizeof(ImDrawIdx) == 2, "ImGuiRenderer draws 16-bit indices, ImGui's default");

rhi::PipelineDesc pipelineDesc(const rhi::Shader& vertex, const rhi::Shader& fragment, rhi::Format target)
{
    rhi::PipelineDesc desc;
    desc.vertex = &vertex;
    desc.fragment = &fragment;
    desc.vertexLayout = {{{sizeof(ImDrawVert), false}},
                         {{0, rhi::VertexFormat::Float2, std::uint32_t(offsetof(ImDrawVert, pos)), 0},
                          {1, rhi::VertexFormat::Float2, std::uint32_t(offsetof(ImDrawVert, uv)), 0},
                          {2, rhi::VertexFormat::UByte4Norm, std::uint32_t(offsetof(ImDrawVert, col)), 0}}};
    desc.cull = rhi::CullMode::None; // ImGui's triangles come in either winding
    rhi::BlendState blend;
    blend.enable = true;
    blend.srcColor = rhi::BlendFactor::SrcAlpha;
    blend.dstColor = rhi::BlendFactor::OneMinusSrcAlpha;
    blend.srcAlpha = rhi::BlendFactor::One;
    blend.dstAlpha = rhi::BlendFactor::OneMinusSrcAlpha;
    desc.colorTargets = {{target, rhi::ColorMask::All, blend}};
    desc.uniformLayouts = {shaders::uniformLayout(kImGuiFrameBlock)};
    desc.debugName = "imgui";
    return desc;
}

} // namespace

ImGuiRenderer::ImGuiRenderer(rhi::Device& device, rhi::Format targetFormat)
    : device_(device), vertex_(device.createShader(imguiVertexShader())),
      fragment_(device.createShader(shaders::load("imgui.frag", {{"BINDING_TEXTURE", kTextureBinding}}))),
      pipeline_(device.createPipeline(pipelineDesc(*vertex_, *fragment_, targetFormat))),
      sampler_(device.createSampler(
          {.magFilter = rhi::Filter::Linear, .minFilter = rhi::Filter::Linear, .debugName = "imgui"})),
      uniforms_(device, "imgui uniforms")
{
    ImGuiIO& io = ImGui::GetIO();
    unsigned char* pixels = nullptr;
    int width = 0;
    int height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    font_ = device.createTexture({.width = std::uint32_t(width),
                                  .height = std::uint32_t(height),
                                  .format = rhi::Format::RGBA8,
                                  .debugName = "imgui font atlas"});
    device.writeTexture(*font_, 0, 0, std::as_bytes(std::span(pixels, std::size_t(width) * std::size_t(height) * 4)));
    // ImGui's texture ids are void*; ours point at const RHI textures.
    io.Fonts->SetTexID(const_cast<rhi::Texture*>(font_.get()));
}

void ImGuiRenderer::reserve(std::size_t vertexBytes, std::size_t indexBytes)
{
    if (!vertices_ || vertices_->desc().size < vertexBytes)
        vertices_ = device_.createBuffer({.size = std::max<std::uint64_t>(vertexBytes * 2, 64 * 1024),
                                          .usage = rhi::BufferUsage::Vertex,
                                          .debugName = "imgui vertices"});
    if (!indices_ || indices_->desc().size < indexBytes)
        indices_ = device_.createBuffer({.size = std::max<std::uint64_t>(indexBytes * 2, 64 * 1024),
                                         .usage = rhi::BufferUsage::Index,
                                         .debugName = "imgui indices"});
}

void ImGuiRenderer::record(rhi::CommandList& commands, const ImDrawData& drawData)
{
    if (drawData.TotalVtxCount == 0)
        return;
    reserve(std::size_t(drawData.TotalVtxCount) * sizeof(ImDrawVert),
            std::size_t(drawData.TotalIdxCount) * sizeof(ImDrawIdx));
    uniforms_.reset();
    const ImVec2 origin = drawData.DisplayPos;
    const ImVec2 size = drawData.DisplaySize;
    const ImGuiFrameUniforms frame{
        {2.0f / size.x, -2.0f / size.y, -1.0f - 2.0f * origin.x / size.x, 1.0f + 2.0f * origin.y / size.y}};

    commands.bindPipeline(*pipeline_);
    rhi::bindUniform(commands, kFrameBinding, uniforms_.push(frame));
    commands.bindVertexBuffer(0, *vertices_);
    commands.bindIndexBuffer(*indices_, rhi::IndexType::UInt16);
    std::uint64_t vertexBytes = 0;
    std::uint64_t indexBytes = 0;
    std::int32_t firstVertex = 0;
    std::uint32_t firstIndex = 0;
    for (int l = 0; l < drawData.CmdListsCount; ++l) {
        const ImDrawList& list = *drawData.CmdLists[l];
        vertices_->write(vertexBytes, std::as_bytes(std::span(list.VtxBuffer.Data, std::size_t(list.VtxBuffer.Size))));
        indices_->write(indexBytes, std::as_bytes(std::span(list.IdxBuffer.Data, std::size_t(list.IdxBuffer.Size))));
        vertexBytes += std::uint64_t(list.VtxBuffer.Size) * sizeof(ImDrawVert);
        indexBytes += std::uint64_t(list.IdxBuffer.Size) * sizeof(ImDrawIdx);
        for (const ImDrawCmd& command : list.CmdBuffer) {
            // Clip rectangles are in display pixels, rows from the top: the RHI's scissor convention.
            const float x0 = std::max(command.ClipRect.x - origin.x, 0.0f);
            const float y0 = std::max(command.ClipRect.y - origin.y, 0.0f);
            const float x1 = std::min(command.ClipRect.z - origin.x, size.x);
            const float y1 = std::min(command.ClipRect.w - origin.y, size.y);
            if (x1 <= x0 || y1 <= y0)
                continue;
            commands.setScissor({std::int32_t(x0), std::int32_t(y0), std::uint32_t(x1 - x0), std::uint32_t(y1 - y0)});
            const auto* texture = static_cast<const rhi::Texture*>(command.GetTexID());
            commands.bindTexture(kTextureBinding, *texture, *sampler_);
            commands.drawIndexed(command.ElemCount, 1, firstIndex + command.IdxOffset,
                                 firstVertex + std::int32_t(command.VtxOffset));
        }
        firstVertex += list.VtxBuffer.Size;
        firstIndex += std::uint32_t(list.IdxBuffer.Size);
    }
}

} // namespace penumbra::viewer
