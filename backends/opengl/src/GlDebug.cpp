#include "GlDebug.hpp"

#include <fmt/format.h>

namespace penumbra::opengl {
namespace {

const char* sourceName(GLenum source)
{
    switch (source) {
    case GL_DEBUG_SOURCE_API:
        return "api";
    case GL_DEBUG_SOURCE_WINDOW_SYSTEM:
        return "window-system";
    case GL_DEBUG_SOURCE_SHADER_COMPILER:
        return "shader-compiler";
    case GL_DEBUG_SOURCE_THIRD_PARTY:
        return "third-party";
    case GL_DEBUG_SOURCE_APPLICATION:
        return "application";
    default:
        return "other";
    }
}

const char* typeName(GLenum type)
{
    switch (type) {
    case GL_DEBUG_TYPE_ERROR:
        return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR:
        return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR:
        return "undefined-behaviour";
    case GL_DEBUG_TYPE_PORTABILITY:
        return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE:
        return "performance";
    case GL_DEBUG_TYPE_MARKER:
        return "marker";
    case GL_DEBUG_TYPE_PUSH_GROUP:
        return "push-group";
    case GL_DEBUG_TYPE_POP_GROUP:
        return "pop-group";
    default:
        return "other";
    }
}

const char* severityName(GLenum severity)
{
    switch (severity) {
    case GL_DEBUG_SEVERITY_HIGH:
        return "high";
    case GL_DEBUG_SEVERITY_MEDIUM:
        return "medium";
    case GL_DEBUG_SEVERITY_LOW:
        return "low";
    default:
        return "notification";
    }
}

// Every message that signals misuse or a problem fails a test: all high/medium/low ones, and
// notifications of a problem type. Other notifications (markers, groups, driver chatter) are noise.
bool indicatesProblem(GLenum type, GLenum severity)
{
    if (severity != GL_DEBUG_SEVERITY_NOTIFICATION)
        return true;
    return type == GL_DEBUG_TYPE_ERROR || type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR ||
           type == GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR || type == GL_DEBUG_TYPE_PORTABILITY ||
           type == GL_DEBUG_TYPE_PERFORMANCE;
}

void APIENTRY debugCallback(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                            const GLchar* message, const void* userParam)
{
    auto* log = static_cast<rhi::DebugMessageLog*>(const_cast<void*>(userParam));
    const std::string text = length >= 0 ? std::string(message, std::size_t(length)) : std::string(message);
    // The application's groups (CommandList::pushLabel) come back in order: messages name the ones open.
    if (source == GL_DEBUG_SOURCE_APPLICATION && type == GL_DEBUG_TYPE_PUSH_GROUP)
        log->openGroup(text);
    if (source == GL_DEBUG_SOURCE_APPLICATION && type == GL_DEBUG_TYPE_POP_GROUP)
        log->closeGroup();
    if (!indicatesProblem(type, severity))
        return;
    log->record(fmt::format("GL {} {} ({}, id {}): {}{}", severityName(severity), typeName(type), sourceName(source),
                            id, text, log->openGroups()));
}

} // namespace

void enableDebugOutput(const GlFunctions& gl, rhi::DebugMessageLog& log)
{
    gl.Enable(GL_DEBUG_OUTPUT);
    gl.Enable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    gl.DebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    gl.DebugMessageCallback(debugCallback, &log);
}

} // namespace penumbra::opengl
