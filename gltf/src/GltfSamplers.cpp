#include "GltfSamplers.hpp"

namespace penumbra::gltf {
namespace {

// The codes of glTF 2.0, section 5.26 (sampler.magFilter, minFilter, wrapS, wrapT), which are OpenGL's.
constexpr int kNearest = 9728;
constexpr int kLinear = 9729;
constexpr int kNearestMipmapNearest = 9984;
constexpr int kLinearMipmapNearest = 9985;
constexpr int kNearestMipmapLinear = 9986;
constexpr int kLinearMipmapLinear = 9987;
constexpr int kClampToEdge = 33071;
constexpr int kMirroredRepeat = 33648;
constexpr int kRepeat = 10497;
constexpr int kUndefined = -1; // tinygltf's value for a filter the file leaves out

scene::TextureFilter magFilter(const Document& document, int code, const std::string& owner)
{
    switch (code) {
    case kUndefined:
    case kLinear:
        return scene::TextureFilter::Linear;
    case kNearest:
        return scene::TextureFilter::Nearest;
    }
    document.fail(fmt::format("{}: magFilter {} is not NEAREST (9728) or LINEAR (9729)", owner, code));
}

void setMinFilter(const Document& document, int code, const std::string& owner, scene::TextureSampler& sampler)
{
    struct Choice {
        int code;
        scene::TextureFilter filter;
        scene::TextureMipFilter mip;
    };
    // An undefined filter is the auto filtering the specification leaves to the renderer: trilinear.
    constexpr Choice choices[] = {
        {kUndefined, scene::TextureFilter::Linear, scene::TextureMipFilter::Linear},
        {kNearest, scene::TextureFilter::Nearest, scene::TextureMipFilter::None},
        {kLinear, scene::TextureFilter::Linear, scene::TextureMipFilter::None},
        {kNearestMipmapNearest, scene::TextureFilter::Nearest, scene::TextureMipFilter::Nearest},
        {kLinearMipmapNearest, scene::TextureFilter::Linear, scene::TextureMipFilter::Nearest},
        {kNearestMipmapLinear, scene::TextureFilter::Nearest, scene::TextureMipFilter::Linear},
        {kLinearMipmapLinear, scene::TextureFilter::Linear, scene::TextureMipFilter::Linear}};
    for (const Choice& c : choices) {
        if (c.code == code) {
            sampler.minFilter = c.filter;
            sampler.mipFilter = c.mip;
            return;
        }
    }
    document.fail(fmt::format("{}: minFilter {} is not one of NEAREST, LINEAR and the four *_MIPMAP_* filters "
                              "(9728, 9729, 9984 to 9987)",
                              owner, code));
}

scene::TextureWrap wrap(const Document& document, int code, const char* field, const std::string& owner)
{
    switch (code) {
    case kRepeat:
        return scene::TextureWrap::Repeat;
    case kClampToEdge:
        return scene::TextureWrap::ClampToEdge;
    case kMirroredRepeat:
        return scene::TextureWrap::MirroredRepeat;
    }
    document.fail(fmt::format("{}: {} {} is not CLAMP_TO_EDGE (33071), MIRRORED_REPEAT (33648) or REPEAT (10497)",
                              owner, field, code));
}

} // namespace

scene::TextureSampler textureSampler(const Document& document, int index, const std::string& owner)
{
    if (index < 0)
        return {};
    const tinygltf::Sampler& gltf = document.at(document.model().samplers, index, "sampler", owner);
    const std::string name = describe("sampler", index, gltf.name);
    scene::TextureSampler sampler;
    sampler.magFilter = magFilter(document, gltf.magFilter, name);
    setMinFilter(document, gltf.minFilter, name, sampler);
    sampler.wrapS = wrap(document, gltf.wrapS, "wrapS", name);
    sampler.wrapT = wrap(document, gltf.wrapT, "wrapT", name);
    return sampler;
}

} // namespace penumbra::gltf
