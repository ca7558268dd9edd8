#include "GlDevice.hpp"

#include "GlCommandList.hpp"
#include "GlFormats.hpp"
#include "GlPipeline.hpp"
#include "GlResources.hpp"
#include "GlSwapchain.hpp"
#include "penumbra/opengl/OpenGLDevice.hpp"

#include <cstring>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

namespace penumbra::opengl {
namespace {

// glGetGraphicsResetStatus's answers (OpenGL 4.5 core specification, section 2.3.2, "Graphics Reset Recovery").
const char* resetStatusName(GLenum status)
{
    switch (status) {
    case GL_GUILTY_CONTEXT_RESET:
        return "GL_GUILTY_CONTEXT_RESET";
    case GL_INNOCENT_CONTEXT_RESET:
        return "GL_INNOCENT_CONTEXT_RESET";
    case GL_UNKNOWN_CONTEXT_RESET:
        return "GL_UNKNOWN_CONTEXT_RESET";
    default:
        return "an unknown reset status";
    }
}

GLint integer(const GlFunctions& gl, GLenum name)
{
    GLint value = 0;
    gl.GetIntegerv(name, &value);
    return value;
}

std::string string(const GlFunctions& gl, GLenum name)
{
    const GLubyte* text = gl.GetString(name);
    return text ? reinterpret_cast<const char*>(text) : "";
}

} // namespace

std::unique_ptr<rhi::Device> createOpenGLDevice(const rhi::DeviceDesc& desc, const OpenGLDeviceOptions& options)
{
    if (desc.backend != "opengl")
        throw rhi::Error(fmt::format("createOpenGLDevice: DeviceDesc::backend is '{}', not 'opengl'", desc.backend));
    return std::make_unique<GlDevice>(desc, options);
}

GlDevice::GlDevice(const rhi::DeviceDesc& desc, const OpenGLDeviceOptions& options)
    : ValidatingDevice(desc.validateUsage), desc_(desc), context_(std::make_shared<GlContext>(desc, options)),
      orientation_(desc.depthRange == rhi::DepthRange::ZeroToOne),
      conventions_(orientation_.conventions(desc.reversedZ))
{
    context_->makeCurrent();
    const GlFunctions& gl = context_->gl();
    if (desc_.validation)
        enableDebugOutput(gl, context_->debugLog());
    orientation_.apply(*context_);
    capabilities_ = queryCapabilities();
    if (desc_.pipelineCache && capabilities_.pipelineBinaries)
        programs_.emplace(gl, desc_.pipelineCache);
    cache_.emplace(gl, std::uint32_t(integer(gl, GL_MAX_UNIFORM_BUFFER_BINDINGS)),
                   std::uint32_t(integer(gl, GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS)));
    resolveRead_ = createName<GlFramebufferName>(*context_, gl.CreateFramebuffers);
    resolveDraw_ = createName<GlFramebufferName>(*context_, gl.CreateFramebuffers);
}

GlDevice::~GlDevice() = default;

rhi::Capabilities GlDevice::queryCapabilities() const
{
    const GlFunctions& gl = context_->gl();
    rhi::Capabilities caps;
    caps.api = "OpenGL " + string(gl, GL_VERSION);
    caps.device = string(gl, GL_RENDERER);
    caps.depthClamp = true; // core since 3.2
    caps.depthBiasClamp = gl.PolygonOffsetClamp != nullptr;
    GLint timestampBits = 0;
    gl.GetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &timestampBits);
    caps.timestamps = timestampBits > 0;
    caps.uniformBufferOffsetAlignment = std::uint32_t(integer(gl, GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT));
    caps.maxUniformBufferRange = std::uint32_t(integer(gl, GL_MAX_UNIFORM_BLOCK_SIZE));
    caps.maxTextureSize = std::uint32_t(integer(gl, GL_MAX_TEXTURE_SIZE));
    caps.maxTextureLayers = std::uint32_t(integer(gl, GL_MAX_ARRAY_TEXTURE_LAYERS));
    caps.cubeArrays = true; // GL_TEXTURE_CUBE_MAP_ARRAY is core since 4.0
    caps.maxCubeSize = std::uint32_t(integer(gl, GL_MAX_CUBE_MAP_TEXTURE_SIZE));
    if (context_->version() >= 46 || context_->hasExtension("GL_ARB_texture_filter_anisotropic") ||
        context_->hasExtension("GL_EXT_texture_filter_anisotropic"))
        gl.GetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &caps.maxSamplerAnisotropy);
    caps.deviceLossReported = integer(gl, GL_RESET_NOTIFICATION_STRATEGY) == GL_LOSE_CONTEXT_ON_RESET;
    // Compute is core since GL 4.3 (section 19, limits in Table 23.64).
    for (GLuint axis = 0; axis < 3; ++axis) {
        GLint size = 0;
        GLint count = 0;
        gl.GetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_SIZE, axis, &size);
        gl.GetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, axis, &count);
        caps.maxWorkgroupSize[axis] = std::uint32_t(size);
        caps.maxWorkgroupCount[axis] = std::uint32_t(count);
    }
    caps.maxWorkgroupInvocations = std::uint32_t(integer(gl, GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS));
    caps.maxComputeSharedMemory = std::uint32_t(integer(gl, GL_MAX_COMPUTE_SHARED_MEMORY_SIZE));
    caps.storageBufferOffsetAlignment = std::uint32_t(integer(gl, GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT));
    caps.maxStorageBufferRange = std::uint64_t(integer(gl, GL_MAX_SHADER_STORAGE_BLOCK_SIZE));
    caps.drawIndirectCount =
        desc_.nativeDrawIndirectCount && gl.MultiDrawArraysIndirectCount && gl.MultiDrawElementsIndirectCount;
    caps.pipelineBinaries = integer(gl, GL_NUM_PROGRAM_BINARY_FORMATS) > 0; // core since 4.1
    for (rhi::Format f : rhi::allFormats)
        caps.formats[std::size_t(f)] = formatSupport(f);
    // GL has no query of a device's memory; Mesa's software renderers keep every texture in system memory.
    if (caps.device.starts_with("llvmpipe") || caps.device.starts_with("softpipe"))
        caps.deviceMemoryBytes = std::uint64_t(::sysconf(_SC_PHYS_PAGES)) * std::uint64_t(::sysconf(_SC_PAGESIZE));
    return caps;
}

// What the driver says of the format for 2D textures (ARB_internalformat_query2, core in GL 4.3).
rhi::FormatSupport GlDevice::formatSupport(rhi::Format format) const
{
    const GlFunctions& gl = context_->gl();
    const GLenum internalFormat = glTextureFormat(format).internalFormat;
    auto query = [&](GLenum name) {
        GLint value = GL_NONE;
        gl.GetInternalformativ(GL_TEXTURE_2D, internalFormat, name, 1, &value);
        return value;
    };
    if (query(GL_INTERNALFORMAT_SUPPORTED) != GL_TRUE)
        return {};
    rhi::FormatSupport support{.sampled = query(GL_FRAGMENT_TEXTURE) == GL_FULL_SUPPORT,
                               .linearFilter = query(GL_FILTER) == GL_FULL_SUPPORT,
                               .renderTarget = query(GL_FRAMEBUFFER_RENDERABLE) == GL_FULL_SUPPORT,
                               .storage = !rhi::isDepthFormat(format) && query(GL_SHADER_IMAGE_LOAD) != GL_NONE &&
                                          query(GL_SHADER_IMAGE_STORE) != GL_NONE};
    if (support.renderTarget)
        support.sampleCounts = 1 | multisampleCounts(internalFormat);
    return support;
}

// The sample counts of GL_TEXTURE_2D_MULTISAMPLE in this format (GL 4.5 section 22.3, GL_NUM_SAMPLE_COUNTS and
// GL_SAMPLES), as a mask of the counts 2, 4 and 8.
std::uint32_t GlDevice::multisampleCounts(GLenum internalFormat) const
{
    const GlFunctions& gl = context_->gl();
    GLint count = 0;
    gl.GetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, internalFormat, GL_NUM_SAMPLE_COUNTS, 1, &count);
    std::vector<GLint> samples(std::size_t(std::max(count, 0)));
    if (!samples.empty())
        gl.GetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, internalFormat, GL_SAMPLES, GLsizei(samples.size()),
                               samples.data());
    std::uint32_t mask = 0;
    for (GLint n : samples)
        if (n == 2 || n == 4 || n == 8)
            mask |= std::uint32_t(n);
    return mask;
}

std::unique_ptr<rhi::Buffer> GlDevice::apiCreateBuffer(const rhi::BufferDesc& desc)
{
    return std::make_unique<GlBuffer>(context_, desc);
}

std::unique_ptr<rhi::Texture> GlDevice::apiCreateTexture(const rhi::TextureDesc& desc)
{
    return std::make_unique<GlTexture>(context_, desc);
}

void GlDevice::apiWriteTexture(rhi::Texture& texture, std::uint32_t layer, std::uint32_t level,
                               std::span<const std::byte> data)
{
    auto& t = glObject<GlTexture>(texture, "writeTexture texture");
    const rhi::TextureDesc& d = t.desc();
    const auto width = GLsizei(rhi::mipExtent(d.width, level));
    const auto height = GLsizei(rhi::mipExtent(d.height, level));
    const GlTextureFormat f = glTextureFormat(d.format);
    std::vector<std::uint32_t> packed;
    const void* pixels = data.data();
    if (d.format == rhi::Format::D24S8) {
        // The RHI's words hold depth in the low 24 bits; GL_UNSIGNED_INT_24_8 wants it in the high 24.
        packed.resize(data.size() / 4);
        std::memcpy(packed.data(), data.data(), data.size());
        for (std::uint32_t& word : packed)
            word <<= 8;
        pixels = packed.data();
    }
    context_->makeCurrent();
    const GlFunctions& gl = context_->gl();
    gl.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (t.isArray())
        gl.TextureSubImage3D(t.name(), GLint(level), 0, 0, GLint(layer), width, height, 1, f.pixelFormat, f.pixelType,
                             pixels);
    else
        gl.TextureSubImage2D(t.name(), GLint(level), 0, 0, width, height, f.pixelFormat, f.pixelType, pixels);
}

std::unique_ptr<rhi::Sampler> GlDevice::apiCreateSampler(const rhi::SamplerDesc& desc)
{
    return std::make_unique<GlSampler>(context_, desc, conventions_);
}

std::unique_ptr<rhi::Shader> GlDevice::apiCreateShader(rhi::CompiledShader compiled)
{
    return std::make_unique<GlShader>(context_, std::move(compiled), orientation_);
}

std::unique_ptr<rhi::Pipeline> GlDevice::apiCreatePipeline(const rhi::PipelineDesc& desc)
{
    return std::make_unique<GlPipeline>(context_, desc, conventions_, programs_ ? &*programs_ : nullptr);
}

std::unique_ptr<rhi::ComputePipeline> GlDevice::apiCreateComputePipeline(const rhi::ComputePipelineDesc& desc)
{
    return std::make_unique<GlComputePipeline>(context_, desc, programs_ ? &*programs_ : nullptr);
}

std::unique_ptr<rhi::Framebuffer> GlDevice::apiCreateFramebuffer(const rhi::FramebufferDesc& desc)
{
    return std::make_unique<GlFramebuffer>(context_, desc);
}

std::unique_ptr<rhi::TimestampQueries> GlDevice::apiCreateTimestampQueries(std::uint32_t count)
{
    return std::make_unique<GlTimestampQueries>(context_, count);
}

std::unique_ptr<rhi::CommandList> GlDevice::createCommandList()
{
    return std::make_unique<GlCommandList>(*this, *context_);
}

std::unique_ptr<rhi::Swapchain> GlDevice::createSwapchain()
{
    return std::make_unique<GlSwapchain>(context_, desc_.window.glfwWindow);
}

void GlDevice::applySubmitDefaults()
{
    const GlFunctions& gl = context_->gl();
    cache_->invalidate();
    gl.Enable(GL_POLYGON_OFFSET_FILL); // the bias is always set, zero when unused
    gl.Enable(GL_PROGRAM_POINT_SIZE); // points take gl_PointSize, as in Vulkan
    gl.Disable(GL_DITHER); // Vulkan does not dither; keep RGBA8 results identical
    gl.Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS); // Vulkan filters across cube faces always
    gl.Enable(GL_FRAMEBUFFER_SRGB); // Vulkan encodes writes to sRGB attachments always
    gl.Enable(GL_MULTISAMPLE); // multisampled framebuffers rasterize per sample, as in Vulkan
    gl.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    cache_->frontFace(orientation_.frontFace());
}

void GlDevice::apiSubmit(rhi::CommandList& commands)
{
    auto& list = glObject<GlCommandList>(commands, "submitted command list");
    if (lost_)
        throw rhi::DeviceLostError(*lost_);
    context_->makeCurrent();
    applySubmitDefaults();
    list.replay({context_->gl(), *cache_, orientation_, conventions_.clearDepth(), ++submitCount_, resolveRead_.get(),
                 resolveDraw_.get()});
    context_->gl().Finish();
    // A lost context answers every call with nothing, so the loss is asked for after each submission. It is reported
    // only by a context made with the lose-context-on-reset strategy (Capabilities::deviceLossReported).
    if (const GLenum status = context_->gl().GetGraphicsResetStatus(); status != GL_NO_ERROR) {
        lost_ = fmt::format("OpenGL context lost during submission {}: {}: the device is lost; make a new one",
                            submitCount_, resetStatusName(status));
        throw rhi::DeviceLostError(*lost_);
    }
    if (desc_.throwOnDebugMessage)
        context_->debugLog().raiseUnreported("OpenGL debug output");
}

std::vector<double> GlDevice::readTimestamps(const rhi::TimestampQueries& queries)
{
    return glObject<const GlTimestampQueries>(queries, "readTimestamps queries").read();
}

std::vector<std::string> GlDevice::debugMessages() const { return context_->debugLog().all(); }

void GlDevice::clearDebugMessages() { context_->debugLog().clear(); }

} // namespace penumbra::opengl
