#include "RawDraws.hpp"

#include "penumbra/opengl/Native.hpp"

namespace penumbra::apps {
namespace {

// What an experienced GL programmer writes for this frame: DSA objects, one
// glBindBufferRange + glDrawElements per mesh, no redundant state.
class RawOpenGLDraws final : public RawDraws {
public:
    RawOpenGLDraws(rhi::Device& device, const DrawScene& scene)
        : device_(device), scene_(scene), gl_(opengl::glFunctions(device)),
          pipeline_(opengl::pipelineNames(scene.pipeline())),
          framebuffer_(opengl::framebufferName(scene.framebuffer())), vertices_(opengl::bufferName(scene.vertices())),
          indices_(opengl::bufferName(scene.indices())), objects_(opengl::bufferName(scene.objects())),
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
        for (std::uint32_t i = 0; i < scene_.count(); ++i) {
            gl_.BindBufferRange(GL_UNIFORM_BUFFER, 0, objects_, GLintptr(scene_.objectStride() * i),
                                DrawScene::objectSize);
            gl_.DrawElements(GL_TRIANGLES, GLsizei(scene_.indexCount()), GL_UNSIGNED_SHORT, nullptr);
        }
        gl_.Finish();
    }

private:
    rhi::Device& device_;
    const DrawScene& scene_;
    const opengl::GlFunctions& gl_;
    opengl::PipelineNames pipeline_;
    GLuint framebuffer_, vertices_, indices_, objects_;
    GLenum nearerFunc_;
};

} // namespace

std::unique_ptr<RawDraws> createRawOpenGLDraws(rhi::Device& device, const DrawScene& scene)
{
    return std::make_unique<RawOpenGLDraws>(device, scene);
}

} // namespace penumbra::apps
