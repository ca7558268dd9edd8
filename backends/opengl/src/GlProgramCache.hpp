#pragma once

#include "GlContext.hpp"

#include "penumbra/rhi/PipelineCache.hpp"

#include <memory>
#include <string>
#include <vector>

namespace penumbra::opengl {

// Linked programs kept as program binaries (GL 4.6 section 7.5 "Program Binaries") in an rhi::PipelineCache,
// entries "opengl" keyed by the driver's vendor, renderer and version and by the program's GLSL. Made only where the
// driver reports binary formats (Capabilities::pipelineBinaries).
class GlProgramCache {
public:
    GlProgramCache(const GlFunctions& gl, std::shared_ptr<rhi::PipelineCache> disk);

    // Links `program` from the binary stored for `key`; false when there is none or the driver refuses it (then a
    // note, and the program is linked from its shaders as if nothing had been stored).
    bool load(const GlFunctions& gl, GLuint program, const std::string& key) const;
    // Before linking from shaders: asks the driver to keep the binary retrievable.
    void prepare(const GlFunctions& gl, GLuint program) const;
    // After a successful link: stores the binary; `linkMs`, what linking took.
    void store(const GlFunctions& gl, GLuint program, const std::string& key, double linkMs) const;

private:
    std::shared_ptr<rhi::PipelineCache> disk_;
    std::string identity_;
    std::vector<GLint> formats_; // GL_PROGRAM_BINARY_FORMATS
};

} // namespace penumbra::opengl
