#include "RawFrames.hpp"

#include "penumbra/opengl/Native.hpp"

#include <cstdint>

namespace penumbra::apps {
namespace {

// What an experienced GL programmer writes for this frame: DSA objects, one glBindBufferRange and one glDrawElements
// (or glDrawElementsIndirect) per mesh, no redundant state.
class RawOpenGLDraws final : public RawFrame {
public:
    RawOpenGLDraws(rhi::Device& device, const DrawScene& scene, DrawCall call)
        : device_(device), scene_(scene), call_(call), gl_(opengl::glFunctions(device)),
          pipeline_(opengl::pipelineNames(scene.pipeline())),
          framebuffer_(opengl::framebufferName(scene.framebuffer())), vertices_(opengl::bufferName(scene.vertices())),
          indices_(opengl::bufferName(scene.indices())), objects_(opengl::bufferName(scene.objects())),
          arguments_(opengl::bufferName(scene.indirectArguments())),
          nearerFunc_(device.conventions().reversedZ() ? GL_GREATER : GL_LESS)
    {
    }

    void frame() override
    {
        opengl::makeCurrent(device_);
        gl_.BindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        gl_.Viewport(0, 0, DrawScene::size, DrawScene::size);
        gl_.Disable(GL_SCISSOR_TEST);
        gl_.Disable(GL_BLEND);
        gl_.ColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        gl_.Enable(GL_DEPTH_TEST);
        gl_.DepthMask(GL_TRUE);
        gl_.DepthFunc(nearerFunc_);
        gl_.Enable(GL_CULL_FACE);
        gl_.CullFace(GL_BACK);
        const GLfloat black[4] = {0, 0, 0, 0};
        const GLfloat farDepth = device_.conventions().clearDepth();
        gl_.ClearNamedFramebufferfv(framebuffer_, GL_COLOR, 0, black);
        gl_.ClearNamedFramebufferfv(framebuffer_, GL_DEPTH, 0, &farDepth);

        gl_.UseProgram(pipeline_.program);
        gl_.BindVertexArray(pipeline_.vertexArray);
        gl_.VertexArrayVertexBuffer(pipeline_.vertexArray, 0, vertices_, 0, sizeof(float) * 3);
        gl_.VertexArrayElementBuffer(pipeline_.vertexArray, indices_);
        gl_.BindBuffer(GL_DRAW_INDIRECT_BUFFER, arguments_);
        for (std::uint32_t i = 0; i < scene_.count(); ++i) {
            gl_.BindBufferRange(GL_UNIFORM_BUFFER, 0, objects_, GLintptr(scene_.objectStride() * i),
                                DrawScene::objectSize);
            if (call_ == DrawCall::Indirect)
                gl_.DrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_SHORT,
                                         reinterpret_cast<const void*>(std::uintptr_t(DrawScene::indirectStride) * i));
            else
                gl_.DrawElements(GL_TRIANGLES, GLsizei(scene_.indexCount()), GL_UNSIGNED_SHORT, nullptr);
        }
        gl_.Finish();
    }

private:
    rhi::Device& device_;
    const DrawScene& scene_;
    DrawCall call_;
    const opengl::GlFunctions& gl_;
    opengl::PipelineNames pipeline_;
    GLuint framebuffer_, vertices_, indices_, objects_, arguments_;
    GLenum nearerFunc_;
};

// What an experienced GL programmer writes for this work: the program and the storage buffer bound once, then each
// glDispatchCompute after a storage barrier for the one before it (GL 4.6 section 7.13.2: incoherent shader writes).
class RawOpenGLDispatches final : public RawFrame {
public:
    RawOpenGLDispatches(rhi::Device& device, const DispatchScene& scene)
        : device_(device), scene_(scene), gl_(opengl::glFunctions(device)),
          program_(opengl::programName(scene.pipeline())), counters_(opengl::bufferName(scene.counters()))
    {
    }

    void frame() override
    {
        opengl::makeCurrent(device_);
        gl_.UseProgram(program_);
        gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, DispatchScene::countersBinding, counters_);
        for (std::uint32_t i = 0; i < scene_.count(); ++i) {
            if (i > 0)
                gl_.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
            gl_.DispatchCompute(1, 1, 1);
        }
        gl_.Finish();
    }

private:
    rhi::Device& device_;
    const DispatchScene& scene_;
    const opengl::GlFunctions& gl_;
    GLuint program_, counters_;
};

} // namespace

std::unique_ptr<RawFrame> createRawOpenGLDraws(rhi::Device& device, const DrawScene& scene, DrawCall call)
{
    return std::make_unique<RawOpenGLDraws>(device, scene, call);
}

std::unique_ptr<RawFrame> createRawOpenGLDispatches(rhi::Device& device, const DispatchScene& scene)
{
    return std::make_unique<RawOpenGLDispatches>(device, scene);
}

} // namespace penumbra::apps
