#include "GltfNodeShadows.hpp"

namespace penumbra::gltf {

NodeShadows readNodeShadows(const Document& document, const tinygltf::Node& node, int index,
                            const NodeShadows& inherited)
{
    NodeShadows shadows = inherited;
    if (!node.extras.IsObject() || !node.extras.Has("penumbra"))
        return shadows;
    const std::string pointer = fmt::format("/nodes/{}/extras/penumbra", index);
    const tinygltf::Value& ours = node.extras.Get("penumbra");
    if (!ours.IsObject())
        document.fail(fmt::format("{}: expected an object with castShadows, receiveShadows and mobility", pointer));
    if (ours.Has("castShadows")) {
        const tinygltf::Value& value = ours.Get("castShadows");
        const std::optional<scene::ShadowCasting> cast =
            value.IsString() ? scene::parseShadowCasting(value.Get<std::string>()) : std::nullopt;
        if (!cast)
            document.fail(
                fmt::format("{}/castShadows: expected one of \"on\", \"off\", \"twoSided\", \"shadowsOnly\"", pointer));
        shadows.cast = *cast;
    }
    if (ours.Has("receiveShadows")) {
        const tinygltf::Value& value = ours.Get("receiveShadows");
        if (!value.IsBool())
            document.fail(fmt::format("{}/receiveShadows: expected true or false", pointer));
        shadows.receive = value.Get<bool>();
    }
    if (ours.Has("mobility")) {
        const tinygltf::Value& value = ours.Get("mobility");
        const std::optional<scene::Mobility> mobility =
            value.IsString() ? scene::parseMobility(value.Get<std::string>()) : std::nullopt;
        if (!mobility)
            document.fail(fmt::format("{}/mobility: expected \"static\" or \"dynamic\"", pointer));
        shadows.mobility = *mobility;
    }
    return shadows;
}

} // namespace penumbra::gltf
