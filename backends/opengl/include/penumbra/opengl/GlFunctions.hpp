#pragma once

// The GL entry points Penumbra loads at run time (we never link libGL). Members drop the `gl`
// prefix so they cannot clash with the gl* symbols that libOSMesa exports: call gl.DrawArrays(...).

#include <GL/glcorearb.h>

namespace penumbra::opengl {

// X(Name, NAME): the function glName with the pointer type PFNGLNAMEPROC from glcorearb.h.
#define PENUMBRA_GL_FUNCTIONS(X)                                                                                       \
    X(ActiveTexture, ACTIVETEXTURE)                                                                                    \
    X(AttachShader, ATTACHSHADER)                                                                                      \
    X(BindBuffer, BINDBUFFER)                                                                                          \
    X(BindBufferBase, BINDBUFFERBASE)                                                                                  \
    X(BindBufferRange, BINDBUFFERRANGE)                                                                                \
    X(BindFramebuffer, BINDFRAMEBUFFER)                                                                                \
    X(BindImageTexture, BINDIMAGETEXTURE)                                                                              \
    X(BindSampler, BINDSAMPLER)                                                                                        \
    X(BindTexture, BINDTEXTURE)                                                                                        \
    X(BindTextureUnit, BINDTEXTUREUNIT)                                                                                \
    X(BindVertexArray, BINDVERTEXARRAY)                                                                                \
    X(BindVertexBuffer, BINDVERTEXBUFFER)                                                                              \
    X(BlendEquationSeparatei, BLENDEQUATIONSEPARATEI)                                                                  \
    X(BlendFuncSeparatei, BLENDFUNCSEPARATEI)                                                                          \
    X(BlitNamedFramebuffer, BLITNAMEDFRAMEBUFFER)                                                                      \
    X(CheckNamedFramebufferStatus, CHECKNAMEDFRAMEBUFFERSTATUS)                                                        \
    X(Clear, CLEAR)                                                                                                    \
    X(ClearColor, CLEARCOLOR)                                                                                          \
    X(ClearDepthf, CLEARDEPTHF)                                                                                        \
    X(ClearNamedFramebufferfv, CLEARNAMEDFRAMEBUFFERFV)                                                                \
    X(ClipControl, CLIPCONTROL)                                                                                        \
    X(ColorMaski, COLORMASKI)                                                                                          \
    X(CompileShader, COMPILESHADER)                                                                                    \
    X(CopyImageSubData, COPYIMAGESUBDATA)                                                                              \
    X(CopyNamedBufferSubData, COPYNAMEDBUFFERSUBDATA)                                                                  \
    X(CreateBuffers, CREATEBUFFERS)                                                                                    \
    X(CreateFramebuffers, CREATEFRAMEBUFFERS)                                                                          \
    X(CreateProgram, CREATEPROGRAM)                                                                                    \
    X(CreateQueries, CREATEQUERIES)                                                                                    \
    X(CreateSamplers, CREATESAMPLERS)                                                                                  \
    X(CreateShader, CREATESHADER)                                                                                      \
    X(CreateTextures, CREATETEXTURES)                                                                                  \
    X(CreateVertexArrays, CREATEVERTEXARRAYS)                                                                          \
    X(CullFace, CULLFACE)                                                                                              \
    X(DebugMessageCallback, DEBUGMESSAGECALLBACK)                                                                      \
    X(DebugMessageControl, DEBUGMESSAGECONTROL)                                                                        \
    X(DeleteBuffers, DELETEBUFFERS)                                                                                    \
    X(DeleteFramebuffers, DELETEFRAMEBUFFERS)                                                                          \
    X(DeleteProgram, DELETEPROGRAM)                                                                                    \
    X(DeleteQueries, DELETEQUERIES)                                                                                    \
    X(DeleteSamplers, DELETESAMPLERS)                                                                                  \
    X(DeleteShader, DELETESHADER)                                                                                      \
    X(DeleteTextures, DELETETEXTURES)                                                                                  \
    X(DeleteVertexArrays, DELETEVERTEXARRAYS)                                                                          \
    X(DebugMessageInsert, DEBUGMESSAGEINSERT)                                                                          \
    X(DepthFunc, DEPTHFUNC)                                                                                            \
    X(DepthMask, DEPTHMASK)                                                                                            \
    X(DetachShader, DETACHSHADER)                                                                                      \
    X(Disable, DISABLE)                                                                                                \
    X(Disablei, DISABLEI)                                                                                              \
    X(DispatchCompute, DISPATCHCOMPUTE)                                                                                \
    X(DispatchComputeIndirect, DISPATCHCOMPUTEINDIRECT)                                                                \
    X(DrawArrays, DRAWARRAYS)                                                                                          \
    X(DrawArraysIndirect, DRAWARRAYSINDIRECT)                                                                          \
    X(DrawArraysInstancedBaseInstance, DRAWARRAYSINSTANCEDBASEINSTANCE)                                                \
    X(DrawElements, DRAWELEMENTS)                                                                                      \
    X(DrawElementsBaseVertex, DRAWELEMENTSBASEVERTEX)                                                                  \
    X(DrawElementsIndirect, DRAWELEMENTSINDIRECT)                                                                      \
    X(DrawElementsInstancedBaseVertexBaseInstance, DRAWELEMENTSINSTANCEDBASEVERTEXBASEINSTANCE)                        \
    X(Enable, ENABLE)                                                                                                  \
    X(EnableVertexArrayAttrib, ENABLEVERTEXARRAYATTRIB)                                                                \
    X(Enablei, ENABLEI)                                                                                                \
    X(Finish, FINISH)                                                                                                  \
    X(FrontFace, FRONTFACE)                                                                                            \
    X(GetError, GETERROR)                                                                                              \
    X(GetGraphicsResetStatus, GETGRAPHICSRESETSTATUS)                                                                  \
    X(GetFloatv, GETFLOATV)                                                                                            \
    X(GetIntegerv, GETINTEGERV)                                                                                        \
    X(GetIntegeri_v, GETINTEGERI_V)                                                                                    \
    X(GetNamedBufferSubData, GETNAMEDBUFFERSUBDATA)                                                                    \
    X(GetInternalformativ, GETINTERNALFORMATIV)                                                                        \
    X(GetProgramBinary, GETPROGRAMBINARY)                                                                              \
    X(GetProgramInfoLog, GETPROGRAMINFOLOG)                                                                            \
    X(GetProgramiv, GETPROGRAMIV)                                                                                      \
    X(GetQueryObjectui64v, GETQUERYOBJECTUI64V)                                                                        \
    X(GetQueryiv, GETQUERYIV)                                                                                          \
    X(GetShaderInfoLog, GETSHADERINFOLOG)                                                                              \
    X(GetShaderiv, GETSHADERIV)                                                                                        \
    X(GetString, GETSTRING)                                                                                            \
    X(GetStringi, GETSTRINGI)                                                                                          \
    X(GetTextureSubImage, GETTEXTURESUBIMAGE)                                                                          \
    X(GetUniformLocation, GETUNIFORMLOCATION)                                                                          \
    X(IsProgram, ISPROGRAM)                                                                                            \
    X(IsVertexArray, ISVERTEXARRAY)                                                                                    \
    X(LinkProgram, LINKPROGRAM)                                                                                        \
    X(MapNamedBufferRange, MAPNAMEDBUFFERRANGE)                                                                        \
    X(MemoryBarrier, MEMORYBARRIER)                                                                                    \
    X(MultiDrawArraysIndirect, MULTIDRAWARRAYSINDIRECT)                                                                \
    X(MultiDrawElementsIndirect, MULTIDRAWELEMENTSINDIRECT)                                                            \
    X(NamedBufferStorage, NAMEDBUFFERSTORAGE)                                                                          \
    X(NamedBufferSubData, NAMEDBUFFERSUBDATA)                                                                          \
    X(NamedFramebufferDrawBuffer, NAMEDFRAMEBUFFERDRAWBUFFER)                                                          \
    X(NamedFramebufferDrawBuffers, NAMEDFRAMEBUFFERDRAWBUFFERS)                                                        \
    X(NamedFramebufferReadBuffer, NAMEDFRAMEBUFFERREADBUFFER)                                                          \
    X(NamedFramebufferTexture, NAMEDFRAMEBUFFERTEXTURE)                                                                \
    X(NamedFramebufferTextureLayer, NAMEDFRAMEBUFFERTEXTURELAYER)                                                      \
    X(ObjectLabel, OBJECTLABEL)                                                                                        \
    X(PixelStorei, PIXELSTOREI)                                                                                        \
    X(PolygonOffset, POLYGONOFFSET)                                                                                    \
    X(PopDebugGroup, POPDEBUGGROUP)                                                                                    \
    X(ProvokingVertex, PROVOKINGVERTEX)                                                                                \
    X(ProgramBinary, PROGRAMBINARY)                                                                                    \
    X(ProgramParameteri, PROGRAMPARAMETERI)                                                                            \
    X(ProgramUniform1i, PROGRAMUNIFORM1I)                                                                              \
    X(PushDebugGroup, PUSHDEBUGGROUP)                                                                                  \
    X(QueryCounter, QUERYCOUNTER)                                                                                      \
    X(ReadPixels, READPIXELS)                                                                                          \
    X(SamplerParameterf, SAMPLERPARAMETERF)                                                                            \
    X(SamplerParameteri, SAMPLERPARAMETERI)                                                                            \
    X(Scissor, SCISSOR)                                                                                                \
    X(ScissorIndexed, SCISSORINDEXED)                                                                                  \
    X(ShaderSource, SHADERSOURCE)                                                                                      \
    X(TextureParameteri, TEXTUREPARAMETERI)                                                                            \
    X(TextureStorage2D, TEXTURESTORAGE2D)                                                                              \
    X(TextureStorage2DMultisample, TEXTURESTORAGE2DMULTISAMPLE)                                                        \
    X(TextureStorage3D, TEXTURESTORAGE3D)                                                                              \
    X(TextureSubImage2D, TEXTURESUBIMAGE2D)                                                                            \
    X(TextureSubImage3D, TEXTURESUBIMAGE3D)                                                                            \
    X(Uniform1i, UNIFORM1I)                                                                                            \
    X(Uniform4fv, UNIFORM4FV)                                                                                          \
    X(UniformMatrix4fv, UNIFORMMATRIX4FV)                                                                              \
    X(UnmapNamedBuffer, UNMAPNAMEDBUFFER)                                                                              \
    X(UseProgram, USEPROGRAM)                                                                                          \
    X(VertexArrayAttribBinding, VERTEXARRAYATTRIBBINDING)                                                              \
    X(VertexArrayAttribFormat, VERTEXARRAYATTRIBFORMAT)                                                                \
    X(VertexArrayBindingDivisor, VERTEXARRAYBINDINGDIVISOR)                                                            \
    X(VertexArrayElementBuffer, VERTEXARRAYELEMENTBUFFER)                                                              \
    X(VertexArrayVertexBuffer, VERTEXARRAYVERTEXBUFFER)                                                                \
    X(Viewport, VIEWPORT)                                                                                              \
    X(ViewportIndexedf, VIEWPORTINDEXEDF)

// The GL 4.5 entry points the backend calls, loaded once per context.
struct GlFunctions {
#define PENUMBRA_GL_MEMBER(name, upper) PFNGL##upper##PROC name = nullptr;
    PENUMBRA_GL_FUNCTIONS(PENUMBRA_GL_MEMBER)
#undef PENUMBRA_GL_MEMBER

    // glPolygonOffsetClamp (4.6) or its ARB/EXT twin; null when the driver offers none of them.
    PFNGLPOLYGONOFFSETCLAMPPROC PolygonOffsetClamp = nullptr;
    // glMulti*IndirectCount (4.6) or their ARB_indirect_parameters twins; null when the driver offers neither.
    PFNGLMULTIDRAWARRAYSINDIRECTCOUNTPROC MultiDrawArraysIndirectCount = nullptr;
    PFNGLMULTIDRAWELEMENTSINDIRECTCOUNTPROC MultiDrawElementsIndirectCount = nullptr;
};

} // namespace penumbra::opengl
