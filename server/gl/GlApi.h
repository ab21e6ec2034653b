#pragma once
// The GL 4.3+ core entry points Specula uses, loaded per context through the platform's
// GetProcAddress. Per context, not global: EGL (glvnd) and OSMesa hand out different pointers,
// and tests create both in one process.
#include <GL/glcorearb.h>

#include <string>

namespace specula::gl {

#define SPECULA_GL_FUNCTIONS(X)                                \
  X(PFNGLGETSTRINGPROC, GetString)                             \
  X(PFNGLGETSTRINGIPROC, GetStringi)                           \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                         \
  X(PFNGLGETINTEGER64VPROC, GetInteger64v)                     \
  X(PFNGLGETINTEGERI_VPROC, GetIntegeri_v)                     \
  X(PFNGLGETERRORPROC, GetError)                               \
  X(PFNGLVIEWPORTPROC, Viewport)                               \
  X(PFNGLCLEARPROC, Clear)                                     \
  X(PFNGLCLEARCOLORPROC, ClearColor)                           \
  X(PFNGLCLEARDEPTHPROC, ClearDepth)                           \
  X(PFNGLCLEARSTENCILPROC, ClearStencil)                       \
  X(PFNGLENABLEPROC, Enable)                                   \
  X(PFNGLDISABLEPROC, Disable)                                 \
  X(PFNGLDEPTHFUNCPROC, DepthFunc)                             \
  X(PFNGLDEPTHMASKPROC, DepthMask)                             \
  X(PFNGLCULLFACEPROC, CullFace)                               \
  X(PFNGLFRONTFACEPROC, FrontFace)                             \
  X(PFNGLBLENDFUNCPROC, BlendFunc)                             \
  X(PFNGLSTENCILFUNCPROC, StencilFunc)                         \
  X(PFNGLSTENCILOPPROC, StencilOp)                             \
  X(PFNGLSTENCILMASKPROC, StencilMask)                         \
  X(PFNGLCOLORMASKPROC, ColorMask)                             \
  X(PFNGLFINISHPROC, Finish)                                   \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                         \
  X(PFNGLREADPIXELSPROC, ReadPixels)                           \
  X(PFNGLGETTEXIMAGEPROC, GetTexImage)                         \
  X(PFNGLGENTEXTURESPROC, GenTextures)                         \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures)                   \
  X(PFNGLBINDTEXTUREPROC, BindTexture)                         \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                     \
  X(PFNGLTEXSTORAGE2DPROC, TexStorage2D)                       \
  X(PFNGLTEXSUBIMAGE2DPROC, TexSubImage2D)                     \
  X(PFNGLTEXSTORAGE3DPROC, TexStorage3D)                       \
  X(PFNGLSCISSORPROC, Scissor)                                 \
  X(PFNGLFRAMEBUFFERTEXTURELAYERPROC, FramebufferTextureLayer) \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                     \
  X(PFNGLBINDIMAGETEXTUREPROC, BindImageTexture)               \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                 \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)           \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                 \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)       \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)   \
  X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                         \
  X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                     \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                           \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                     \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                           \
  X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                   \
  X(PFNGLBINDBUFFERRANGEPROC, BindBufferRange)                 \
  X(PFNGLCOPYBUFFERSUBDATAPROC, CopyBufferSubData)             \
  X(PFNGLDRAWARRAYSINDIRECTPROC, DrawArraysIndirect)           \
  X(PFNGLMULTIDRAWARRAYSINDIRECTPROC, MultiDrawArraysIndirect) \
  X(PFNGLDRAWELEMENTSINDIRECTPROC, DrawElementsIndirect)       \
  X(PFNGLBUFFERDATAPROC, BufferData)                           \
  X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                     \
  X(PFNGLGETBUFFERSUBDATAPROC, GetBufferSubData)               \
  X(PFNGLBUFFERSTORAGEPROC, BufferStorage)                     \
  X(PFNGLMAPBUFFERRANGEPROC, MapBufferRange)                   \
  X(PFNGLUNMAPBUFFERPROC, UnmapBuffer)                         \
  X(PFNGLFENCESYNCPROC, FenceSync)                             \
  X(PFNGLCLIENTWAITSYNCPROC, ClientWaitSync)                   \
  X(PFNGLDELETESYNCPROC, DeleteSync)                           \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                 \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)           \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                 \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray) \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)         \
  X(PFNGLDRAWELEMENTSPROC, DrawElements)                       \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                           \
  X(PFNGLPATCHPARAMETERIPROC, PatchParameteri)                 \
  X(PFNGLCREATESHADERPROC, CreateShader)                       \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                       \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                     \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                         \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)               \
  X(PFNGLDELETESHADERPROC, DeleteShader)                       \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                     \
  X(PFNGLATTACHSHADERPROC, AttachShader)                       \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                         \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                       \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)             \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                     \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                           \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)           \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                             \
  X(PFNGLUNIFORM1UIPROC, Uniform1ui)                           \
  X(PFNGLUNIFORM1FPROC, Uniform1f)                             \
  X(PFNGLUNIFORM2IPROC, Uniform2i)                             \
  X(PFNGLUNIFORM4IPROC, Uniform4i)                             \
  X(PFNGLUNIFORM2FPROC, Uniform2f)                             \
  X(PFNGLUNIFORM3FVPROC, Uniform3fv)                           \
  X(PFNGLUNIFORM4FVPROC, Uniform4fv)                           \
  X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)               \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)               \
  X(PFNGLDISPATCHCOMPUTEPROC, DispatchCompute)                 \
  X(PFNGLDISPATCHCOMPUTEINDIRECTPROC, DispatchComputeIndirect) \
  X(PFNGLMEMORYBARRIERPROC, MemoryBarrier)                     \
  X(PFNGLGENQUERIESPROC, GenQueries)                           \
  X(PFNGLDELETEQUERIESPROC, DeleteQueries)                     \
  X(PFNGLQUERYCOUNTERPROC, QueryCounter)                       \
  X(PFNGLGETQUERYOBJECTUI64VPROC, GetQueryObjectui64v)

// One loaded function table. Members are named after the GL function without its prefix:
// gl.Clear(...) calls glClear of this context.
struct GlApi {
#define SPECULA_GL_DECLARE(type, name) type name = nullptr;
  SPECULA_GL_FUNCTIONS(SPECULA_GL_DECLARE)
#undef SPECULA_GL_DECLARE

  using ProcLoader = void* (*)(const char* name, void* user);
  // Loads every entry point; returns the names that could not be found (empty on success).
  std::string load(ProcLoader loader, void* user);
};

}  // namespace specula::gl
