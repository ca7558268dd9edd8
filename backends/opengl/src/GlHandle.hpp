#pragma once

// Owning GL names. Each deletes its name exactly once, with its context current, when it goes out
// of scope, so a constructor that throws half-way deletes what it had already created: members
// that are fully constructed are destroyed even when the enclosing constructor fails (C++ Core
// Guidelines R.1 "Manage resources automatically using resource handles and RAII", E.6).

#include "GlContext.hpp"

#include <utility>

namespace penumbra::opengl {

using GlDelete = void (*)(const GlFunctions& gl, GLuint name);

// A name created in `context`, which must outlive it: owners keep the context's shared_ptr in a
// member declared before their names.
template <GlDelete destroy>
class GlName {
public:
    GlName() = default;
    GlName(const GlContext& context, GLuint name) : context_(&context), name_(name) {}
    ~GlName() { reset(); }
    GlName(GlName&& other) noexcept : context_(other.context_), name_(std::exchange(other.name_, 0)) {}
    GlName& operator=(GlName&& other) noexcept
    {
        if (this != &other) {
            reset();
            context_ = other.context_;
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }

    GLuint get() const { return name_; }
    void reset()
    {
        if (name_ == 0)
            return;
        context_->makeCurrent();
        destroy(context_->gl(), std::exchange(name_, 0));
    }

private:
    const GlContext* context_ = nullptr;
    GLuint name_ = 0;
};

namespace deleters {
inline void buffer(const GlFunctions& gl, GLuint name) { gl.DeleteBuffers(1, &name); }
inline void framebuffer(const GlFunctions& gl, GLuint name) { gl.DeleteFramebuffers(1, &name); }
inline void program(const GlFunctions& gl, GLuint name) { gl.DeleteProgram(name); }
inline void query(const GlFunctions& gl, GLuint name) { gl.DeleteQueries(1, &name); }
inline void sampler(const GlFunctions& gl, GLuint name) { gl.DeleteSamplers(1, &name); }
inline void shader(const GlFunctions& gl, GLuint name) { gl.DeleteShader(name); }
inline void texture(const GlFunctions& gl, GLuint name) { gl.DeleteTextures(1, &name); }
inline void vertexArray(const GlFunctions& gl, GLuint name) { gl.DeleteVertexArrays(1, &name); }
} // namespace deleters

using GlBufferName = GlName<deleters::buffer>;
using GlFramebufferName = GlName<deleters::framebuffer>;
using GlProgramName = GlName<deleters::program>;
using GlQueryName = GlName<deleters::query>;
using GlSamplerName = GlName<deleters::sampler>;
using GlShaderName = GlName<deleters::shader>;
using GlTextureName = GlName<deleters::texture>;
using GlVertexArrayName = GlName<deleters::vertexArray>;

// Creates one name with a glCreate* entry point of the DSA shape (count, names): buffers,
// framebuffers, samplers, vertex arrays.
template <typename Name>
Name createName(const GlContext& context, void (*create)(GLsizei, GLuint*))
{
    GLuint name = 0;
    create(1, &name);
    return Name(context, name);
}

} // namespace penumbra::opengl
