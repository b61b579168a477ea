#include "vtkPPIRayComputeProgram.h"

#include "ppirayVTKCompatibility.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include PPIRAY_VTK_OPENGL_HEADER

#include <vector>

vtkStandardNewMacro(vtkPPIRayComputeProgram);

namespace
{
// The info log of a shader or program (`get` glGetShaderInfoLog or
// glGetProgramInfoLog, `length` its GL_INFO_LOG_LENGTH).
template<typename Get>
std::string InfoLog(GLuint object, GLint length, Get get)
{
  std::vector<char> log(static_cast<size_t>(length > 0 ? length : 1), '\0');
  get(object, static_cast<GLsizei>(log.size()), nullptr, log.data());
  return std::string(log.data());
}
}

//------------------------------------------------------------------------------
vtkPPIRayComputeProgram::vtkPPIRayComputeProgram() = default;

//------------------------------------------------------------------------------
vtkPPIRayComputeProgram::~vtkPPIRayComputeProgram() = default;

//------------------------------------------------------------------------------
bool vtkPPIRayComputeProgram::IsSupported(vtkOpenGLRenderWindow* context)
{
  if (!context)
  {
    return false;
  }
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  return (major > 4 || (major == 4 && minor >= 3)) && glDispatchCompute != nullptr;
}

//------------------------------------------------------------------------------
bool vtkPPIRayComputeProgram::Build(const std::string& source)
{
  const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint status = 0, length = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &status);
  if (!status)
  {
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    this->Error = "compute shader: " + InfoLog(shader, length, glGetShaderInfoLog);
    glDeleteShader(shader);
    return false;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  glDetachShader(program, shader);
  glDeleteShader(shader);
  glGetProgramiv(program, GL_LINK_STATUS, &status);
  if (!status)
  {
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    this->Error = "compute program: " + InfoLog(program, length, glGetProgramInfoLog);
    glDeleteProgram(program);
    return false;
  }
  this->Handle = static_cast<int>(program);
  this->Linked = true;
  this->Compiled = true;
  this->Error.clear();
  return true;
}

//------------------------------------------------------------------------------
void vtkPPIRayComputeProgram::Dispatch(int width, int height, int groupWidth, int groupHeight)
{
  glDispatchCompute(static_cast<GLuint>((width + groupWidth - 1) / groupWidth),
    static_cast<GLuint>((height + groupHeight - 1) / groupHeight), 1);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
}
