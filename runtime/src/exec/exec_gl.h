// The GL entry points the executor calls (ARB programs, and GL 2.0 shader objects for the
// GLSL engine), loaded through the context's GetProcAddress
// (OSMesaGetProcAddress or eglGetProcAddress): nothing refers to libGL's symbols.
#pragma once

#include <GL/gl.h>
#include <GL/glext.h>

#include <functional>
#include <string>

namespace arbiter::runtime::exec {

// X(type, member, "glName"). Entry points up to GL 1.3 take their type from gl.h's prototype
// (decltype does not refer to the symbol), later ones from glext.h's PFN types.
#define ARBITER_EXEC_GL_FUNCTIONS(X)                                                              \
  X(decltype(&glGetError), GetError, "glGetError")                                                \
  X(decltype(&glGetIntegerv), GetIntegerv, "glGetIntegerv")                                       \
  X(decltype(&glGetString), GetString, "glGetString")                                             \
  X(decltype(&glEnable), Enable, "glEnable")                                                      \
  X(decltype(&glDisable), Disable, "glDisable")                                                   \
  X(decltype(&glViewport), Viewport, "glViewport")                                                \
  X(decltype(&glClearColor), ClearColor, "glClearColor")                                          \
  X(decltype(&glClear), Clear, "glClear")                                                         \
  X(decltype(&glFinish), Finish, "glFinish")                                                      \
  X(decltype(&glReadBuffer), ReadBuffer, "glReadBuffer")                                          \
  X(decltype(&glReadPixels), ReadPixels, "glReadPixels")                                          \
  X(decltype(&glPixelStorei), PixelStorei, "glPixelStorei")                                       \
  X(decltype(&glMatrixMode), MatrixMode, "glMatrixMode")                                          \
  X(decltype(&glLoadMatrixf), LoadMatrixf, "glLoadMatrixf")                                       \
  X(decltype(&glLoadIdentity), LoadIdentity, "glLoadIdentity")                                    \
  X(decltype(&glMaterialfv), Materialfv, "glMaterialfv")                                          \
  X(decltype(&glMaterialf), Materialf, "glMaterialf")                                             \
  X(decltype(&glLightfv), Lightfv, "glLightfv")                                                   \
  X(decltype(&glLightf), Lightf, "glLightf")                                                      \
  X(decltype(&glLightModelfv), LightModelfv, "glLightModelfv")                                    \
  X(decltype(&glTexGenfv), TexGenfv, "glTexGenfv")                                                \
  X(decltype(&glFogfv), Fogfv, "glFogfv")                                                         \
  X(decltype(&glFogf), Fogf, "glFogf")                                                            \
  X(decltype(&glClipPlane), ClipPlane, "glClipPlane")                                             \
  X(decltype(&glPointSize), PointSize, "glPointSize")                                             \
  X(decltype(&glTexEnvfv), TexEnvfv, "glTexEnvfv")                                                \
  X(decltype(&glDepthRange), DepthRange, "glDepthRange")                                          \
  X(decltype(&glBegin), Begin, "glBegin")                                                         \
  X(decltype(&glEnd), End, "glEnd")                                                               \
  X(decltype(&glVertex4fv), Vertex4fv, "glVertex4fv")                                             \
  X(decltype(&glNormal3fv), Normal3fv, "glNormal3fv")                                             \
  X(decltype(&glColor4fv), Color4fv, "glColor4fv")                                                \
  X(decltype(&glGenTextures), GenTextures, "glGenTextures")                                       \
  X(decltype(&glDeleteTextures), DeleteTextures, "glDeleteTextures")                              \
  X(decltype(&glBindTexture), BindTexture, "glBindTexture")                                       \
  X(decltype(&glTexParameteri), TexParameteri, "glTexParameteri")                                 \
  X(decltype(&glTexImage1D), TexImage1D, "glTexImage1D")                                          \
  X(decltype(&glTexImage2D), TexImage2D, "glTexImage2D")                                          \
  X(decltype(&glTexImage3D), TexImage3D, "glTexImage3D")                                          \
  X(decltype(&glActiveTexture), ActiveTexture, "glActiveTexture")                                 \
  X(decltype(&glMultiTexCoord4fv), MultiTexCoord4fv, "glMultiTexCoord4fv")                        \
  X(decltype(&glPushAttrib), PushAttrib, "glPushAttrib")                                          \
  X(decltype(&glPopAttrib), PopAttrib, "glPopAttrib")                                             \
  X(decltype(&glPushClientAttrib), PushClientAttrib, "glPushClientAttrib")                        \
  X(decltype(&glPopClientAttrib), PopClientAttrib, "glPopClientAttrib")                           \
  X(decltype(&glColorMask), ColorMask, "glColorMask")                                             \
  X(decltype(&glBlendFunc), BlendFunc, "glBlendFunc")                                             \
  X(decltype(&glClearDepth), ClearDepth, "glClearDepth")                                          \
  X(decltype(&glDepthFunc), DepthFunc, "glDepthFunc")                                             \
  X(decltype(&glShadeModel), ShadeModel, "glShadeModel")                                          \
  X(decltype(&glHint), Hint, "glHint")                                                            \
  X(decltype(&glOrtho), Ortho, "glOrtho")                                                         \
  X(decltype(&glFrustum), Frustum, "glFrustum")                                                   \
  X(decltype(&glDrawArrays), DrawArrays, "glDrawArrays")                                          \
  X(decltype(&glVertexPointer), VertexPointer, "glVertexPointer")                                 \
  X(decltype(&glNormalPointer), NormalPointer, "glNormalPointer")                                 \
  X(decltype(&glColorPointer), ColorPointer, "glColorPointer")                                    \
  X(decltype(&glTexCoordPointer), TexCoordPointer, "glTexCoordPointer")                           \
  X(decltype(&glEnableClientState), EnableClientState, "glEnableClientState")                     \
  X(decltype(&glDisableClientState), DisableClientState, "glDisableClientState")                  \
  X(decltype(&glClientActiveTexture), ClientActiveTexture, "glClientActiveTexture")               \
  X(decltype(&glGetFloatv), GetFloatv, "glGetFloatv")                                             \
  X(decltype(&glGetClipPlane), GetClipPlane, "glGetClipPlane")                                    \
  X(decltype(&glTexParameterfv), TexParameterfv, "glTexParameterfv")                              \
  X(decltype(&glTexParameterf), TexParameterf, "glTexParameterf")                                 \
  X(decltype(&glPolygonMode), PolygonMode, "glPolygonMode")                                       \
  X(PFNGLSECONDARYCOLORPOINTERPROC, SecondaryColorPointer, "glSecondaryColorPointer")             \
  X(PFNGLFOGCOORDPOINTERPROC, FogCoordPointer, "glFogCoordPointer")                               \
  X(PFNGLGETATTRIBLOCATIONPROC, GetAttribLocation, "glGetAttribLocation")                         \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer, "glVertexAttribPointer")                   \
  X(PFNGLVERTEXATTRIBIPOINTERPROC, VertexAttribIPointer, "glVertexAttribIPointer")                \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray, "glEnableVertexAttribArray")       \
  X(PFNGLDISABLEVERTEXATTRIBARRAYPROC, DisableVertexAttribArray, "glDisableVertexAttribArray")    \
  X(PFNGLGENERATEMIPMAPPROC, GenerateMipmap, "glGenerateMipmap")                                  \
  X(PFNGLUNIFORM1FVPROC, Uniform1fv, "glUniform1fv")                                              \
  X(PFNGLUNIFORM2FVPROC, Uniform2fv, "glUniform2fv")                                              \
  X(PFNGLUNIFORM3FVPROC, Uniform3fv, "glUniform3fv")                                              \
  X(PFNGLUNIFORM1IVPROC, Uniform1iv, "glUniform1iv")                                              \
  X(PFNGLUNIFORM2IVPROC, Uniform2iv, "glUniform2iv")                                              \
  X(PFNGLUNIFORM3IVPROC, Uniform3iv, "glUniform3iv")                                              \
  X(PFNGLUNIFORM4IVPROC, Uniform4iv, "glUniform4iv")                                              \
  X(PFNGLUNIFORM1UIVPROC, Uniform1uiv, "glUniform1uiv")                                           \
  X(PFNGLUNIFORM2UIVPROC, Uniform2uiv, "glUniform2uiv")                                           \
  X(PFNGLUNIFORM3UIVPROC, Uniform3uiv, "glUniform3uiv")                                           \
  X(PFNGLUNIFORM4UIVPROC, Uniform4uiv, "glUniform4uiv")                                           \
  X(PFNGLUNIFORMMATRIX2FVPROC, UniformMatrix2fv, "glUniformMatrix2fv")                            \
  X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv, "glUniformMatrix3fv")                            \
  X(PFNGLUNIFORMMATRIX2X3FVPROC, UniformMatrix2x3fv, "glUniformMatrix2x3fv")                      \
  X(PFNGLUNIFORMMATRIX2X4FVPROC, UniformMatrix2x4fv, "glUniformMatrix2x4fv")                      \
  X(PFNGLUNIFORMMATRIX3X2FVPROC, UniformMatrix3x2fv, "glUniformMatrix3x2fv")                      \
  X(PFNGLUNIFORMMATRIX3X4FVPROC, UniformMatrix3x4fv, "glUniformMatrix3x4fv")                      \
  X(PFNGLUNIFORMMATRIX4X2FVPROC, UniformMatrix4x2fv, "glUniformMatrix4x2fv")                      \
  X(PFNGLUNIFORMMATRIX4X3FVPROC, UniformMatrix4x3fv, "glUniformMatrix4x3fv")                      \
  X(PFNGLSECONDARYCOLOR3FVPROC, SecondaryColor3fv, "glSecondaryColor3fv")                         \
  X(PFNGLFOGCOORDFPROC, FogCoordf, "glFogCoordf")                                                 \
  X(PFNGLPOINTPARAMETERFPROC, PointParameterf, "glPointParameterf")                               \
  X(PFNGLPOINTPARAMETERFVPROC, PointParameterfv, "glPointParameterfv")                            \
  X(PFNGLCLAMPCOLORARBPROC, ClampColorARB, "glClampColorARB")                                     \
  X(PFNGLDRAWBUFFERSPROC, DrawBuffers, "glDrawBuffers")                                           \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers, "glGenFramebuffers")                               \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers, "glDeleteFramebuffers")                      \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer, "glBindFramebuffer")                               \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer, "glFramebufferRenderbuffer")       \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus, "glCheckFramebufferStatus")          \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers, "glGenRenderbuffers")                            \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers, "glDeleteRenderbuffers")                   \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer, "glBindRenderbuffer")                            \
  X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage, "glRenderbufferStorage")                   \
  X(PFNGLVERTEXATTRIB4FVARBPROC, VertexAttrib4fvARB, "glVertexAttrib4fvARB")                      \
  X(PFNGLGENPROGRAMSARBPROC, GenProgramsARB, "glGenProgramsARB")                                  \
  X(PFNGLDELETEPROGRAMSARBPROC, DeleteProgramsARB, "glDeleteProgramsARB")                         \
  X(PFNGLBINDPROGRAMARBPROC, BindProgramARB, "glBindProgramARB")                                  \
  X(PFNGLPROGRAMSTRINGARBPROC, ProgramStringARB, "glProgramStringARB")                            \
  X(PFNGLGETPROGRAMIVARBPROC, GetProgramivARB, "glGetProgramivARB")                               \
  X(PFNGLPROGRAMENVPARAMETER4FVARBPROC, ProgramEnvParameter4fvARB, "glProgramEnvParameter4fvARB") \
  X(PFNGLPROGRAMLOCALPARAMETER4FVARBPROC, ProgramLocalParameter4fvARB,                            \
    "glProgramLocalParameter4fvARB")                                                              \
  X(PFNGLCREATESHADERPROC, CreateShader, "glCreateShader")                                        \
  X(PFNGLSHADERSOURCEPROC, ShaderSource, "glShaderSource")                                        \
  X(PFNGLCOMPILESHADERPROC, CompileShader, "glCompileShader")                                     \
  X(PFNGLGETSHADERIVPROC, GetShaderiv, "glGetShaderiv")                                           \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog, "glGetShaderInfoLog")                            \
  X(PFNGLDELETESHADERPROC, DeleteShader, "glDeleteShader")                                        \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram, "glCreateProgram")                                     \
  X(PFNGLATTACHSHADERPROC, AttachShader, "glAttachShader")                                        \
  X(PFNGLBINDATTRIBLOCATIONPROC, BindAttribLocation, "glBindAttribLocation")                      \
  X(PFNGLLINKPROGRAMPROC, LinkProgram, "glLinkProgram")                                           \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv, "glGetProgramiv")                                        \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog, "glGetProgramInfoLog")                         \
  X(PFNGLUSEPROGRAMPROC, UseProgram, "glUseProgram")                                              \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram, "glDeleteProgram")                                     \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation, "glGetUniformLocation")                      \
  X(PFNGLUNIFORM4FVPROC, Uniform4fv, "glUniform4fv")                                              \
  X(PFNGLUNIFORM1IPROC, Uniform1i, "glUniform1i")                                                 \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv, "glUniformMatrix4fv")                            \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays, "glGenVertexArrays")                               \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray, "glBindVertexArray")                               \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays, "glDeleteVertexArrays")                      \
  X(PFNGLGENBUFFERSPROC, GenBuffers, "glGenBuffers")                                              \
  X(PFNGLBINDBUFFERPROC, BindBuffer, "glBindBuffer")                                              \
  X(PFNGLBUFFERDATAPROC, BufferData, "glBufferData")                                              \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers, "glDeleteBuffers")                                     \
  X(PFNGLDEPTHRANGEFPROC, DepthRangef, "glDepthRangef")

struct ExecGl {
#define ARBITER_EXEC_GL_MEMBER(type, member, name) type member = nullptr;
  ARBITER_EXEC_GL_FUNCTIONS(ARBITER_EXEC_GL_MEMBER)
#undef ARBITER_EXEC_GL_MEMBER
};

// A GL entry point of unknown type, and the context's lookup by name (OSMesaGetProcAddress,
// eglGetProcAddress); null when unknown.
using GlProc = void (*)();
using GetProcFn = std::function<GlProc(const char* name)>;

// Loads every entry point of `gl` through `get_proc`; false (naming the missing one in
// `error`) when one is unknown.
[[nodiscard]] bool LoadExecGl(const GetProcFn& get_proc, ExecGl* gl, std::string* error);

// "GL_INVALID_OPERATION" etc. for an error code.
std::string GlErrorName(GLenum error);

}  // namespace arbiter::runtime::exec
