#include "GlProgramCache.hpp"

#include <algorithm>
#include <cstring>
#include <fmt/format.h>

namespace penumbra::opengl {
namespace {

constexpr std::string_view kProgramCacheKind = "opengl";

std::string text(const GlFunctions& gl, GLenum name)
{
    const auto* value = reinterpret_cast<const char*>(gl.GetString(name));
    return value ? value : "";
}

} // namespace

GlProgramCache::GlProgramCache(const GlFunctions& gl, std::shared_ptr<rhi::PipelineCache> disk)
    : disk_(std::move(disk)),
      identity_(fmt::format("OpenGL {} | {} | {}", text(gl, GL_VENDOR), text(gl, GL_RENDERER), text(gl, GL_VERSION)))
{
    GLint count = 0;
    gl.GetIntegerv(GL_NUM_PROGRAM_BINARY_FORMATS, &count);
    formats_.resize(std::size_t(std::max(count, 0)));
    if (!formats_.empty())
        gl.GetIntegerv(GL_PROGRAM_BINARY_FORMATS, formats_.data());
}

bool GlProgramCache::load(const GlFunctions& gl, GLuint program, const std::string& key) const
{
    const std::optional<std::string> stored = disk_->load(kProgramCacheKind, identity_, key);
    if (!stored)
        return false;
    // The payload: the binary's format, then the binary.
    GLenum format = GL_NONE;
    if (stored->size() <= sizeof(format)) {
        disk_->refuse(kProgramCacheKind, identity_, key, "no program binary after its format");
        return false;
    }
    std::memcpy(&format, stored->data(), sizeof(format));
    // A format the driver does not list would be a GL error (INVALID_ENUM) in the debug output.
    if (std::find(formats_.begin(), formats_.end(), GLint(format)) == formats_.end()) {
        disk_->refuse(kProgramCacheKind, identity_, key,
                      fmt::format("binary format {:#x}, which the driver does not list", format));
        return false;
    }
    gl.ProgramBinary(program, format, stored->data() + sizeof(format), GLsizei(stored->size() - sizeof(format)));
    GLint ok = GL_FALSE;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok)
        disk_->refuse(kProgramCacheKind, identity_, key, "the driver refused the program binary");
    return ok == GL_TRUE;
}

void GlProgramCache::prepare(const GlFunctions& gl, GLuint program) const
{
    gl.ProgramParameteri(program, GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
}

void GlProgramCache::store(const GlFunctions& gl, GLuint program, const std::string& key, double linkMs) const
{
    GLint length = 0;
    gl.GetProgramiv(program, GL_PROGRAM_BINARY_LENGTH, &length);
    if (length <= 0)
        return;
    GLenum format = GL_NONE;
    std::string payload(sizeof(format) + std::size_t(length), '\0');
    GLsizei written = 0;
    gl.GetProgramBinary(program, length, &written, &format, payload.data() + sizeof(format));
    std::memcpy(payload.data(), &format, sizeof(format));
    payload.resize(sizeof(format) + std::size_t(written));
    disk_->store(kProgramCacheKind, identity_, key, payload, linkMs);
}

} // namespace penumbra::opengl
