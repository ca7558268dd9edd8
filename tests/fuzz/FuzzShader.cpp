// libFuzzer target: the GLSL compile path a user's shader takes (rhi::compileShader: glslang with the
// include list, SPIR-V, reflection). The input is a fragment shader; lines "//@include NAME" start an
// include of that name, which the source may #include "NAME".
#include "penumbra/rhi/Error.hpp"
#include "penumbra/rhi/Shader.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string text(reinterpret_cast<const char*>(data), size);
    penumbra::rhi::ShaderSource source{.stage = penumbra::rhi::ShaderStage::Fragment, .name = "fuzz.frag"};
    constexpr std::string_view kMarker = "//@include ";
    std::string* current = &source.source;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string line = text.substr(start, end - start);
        if (line.rfind(kMarker, 0) == 0) {
            source.includes.push_back({line.substr(kMarker.size()), ""});
            current = &source.includes.back().source;
        } else {
            *current += line + "\n";
        }
        start = end + 1;
    }
    try {
        penumbra::rhi::compileShader(source, "");
    } catch (const penumbra::rhi::Error&) {
    }
    return 0;
}
