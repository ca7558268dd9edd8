// libFuzzer target: the shadow settings JSON (shadows::parseShadowSettings); a bad file throws rhi::Error.
#include "penumbra/rhi/Error.hpp"
#include "penumbra/shadows/ShadowSettingsJson.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    try {
        const penumbra::shadows::ShadowSettings settings =
            penumbra::shadows::parseShadowSettings({reinterpret_cast<const char*>(data), size}, "fuzz.json");
        // What parses writes back and parses to the same settings.
        const std::string json = penumbra::shadows::toJson(settings);
        if (penumbra::shadows::toJson(penumbra::shadows::parseShadowSettings(json, "round trip")) != json)
            __builtin_trap();
    } catch (const penumbra::rhi::Error&) {
    }
    return 0;
}
