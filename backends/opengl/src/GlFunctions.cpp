#include "GlContext.hpp"

#include "penumbra/rhi/Error.hpp"

#include <fmt/format.h>
#include <type_traits>

namespace penumbra::opengl {

GlFunctions loadGlFunctions(const PlatformContext& loader, bool polygonOffsetClamp, bool indirectCount)
{
    GlFunctions gl;
    auto load = [&](auto& member, const char* name) {
        member = reinterpret_cast<std::remove_reference_t<decltype(member)>>(loader.procAddress(name));
        if (!member)
            throw rhi::Error(fmt::format("OpenGL: the driver does not provide {}", name));
    };
#define PENUMBRA_GL_LOAD(name, upper) load(gl.name, "gl" #name);
    PENUMBRA_GL_FUNCTIONS(PENUMBRA_GL_LOAD)
#undef PENUMBRA_GL_LOAD
    // Proc lookups succeed even for names the driver lacks, so the caller decides from the extension list.
    if (polygonOffsetClamp) {
        for (const char* name : {"glPolygonOffsetClamp", "glPolygonOffsetClampARB", "glPolygonOffsetClampEXT"})
            if (GlProc proc = loader.procAddress(name); proc && !gl.PolygonOffsetClamp)
                gl.PolygonOffsetClamp = reinterpret_cast<PFNGLPOLYGONOFFSETCLAMPPROC>(proc);
    }
    // The ARB functions take the same arguments as the 4.6 ones (ARB_indirect_parameters, "New Procedures").
    if (indirectCount) {
        for (const char* name : {"glMultiDrawArraysIndirectCount", "glMultiDrawArraysIndirectCountARB"})
            if (GlProc proc = loader.procAddress(name); proc && !gl.MultiDrawArraysIndirectCount)
                gl.MultiDrawArraysIndirectCount = reinterpret_cast<PFNGLMULTIDRAWARRAYSINDIRECTCOUNTPROC>(proc);
        for (const char* name : {"glMultiDrawElementsIndirectCount", "glMultiDrawElementsIndirectCountARB"})
            if (GlProc proc = loader.procAddress(name); proc && !gl.MultiDrawElementsIndirectCount)
                gl.MultiDrawElementsIndirectCount = reinterpret_cast<PFNGLMULTIDRAWELEMENTSINDIRECTCOUNTPROC>(proc);
    }
    return gl;
}

} // namespace penumbra::opengl
