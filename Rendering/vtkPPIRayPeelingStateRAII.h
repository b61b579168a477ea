/**
 * @class   vtkPPIRayPeelingStateRAII
 * @brief   the OpenGL state a PPIRay frame changes, saved on construction and restored on
 * destruction
 *
 * As VTK's vtkVolumeStateRAII: every state the peel loop and the composite
 * set (viewport, blending, depth test, mask and function, face culling and
 * its mode, scissor test, clear colour, colour mask) goes back through
 * vtkOpenGLState to what it was, whichever way the frame returns. Internal to
 * PPIRay::Rendering.
 */
#ifndef vtkPPIRayPeelingStateRAII_h
#define vtkPPIRayPeelingStateRAII_h

#include "ppirayVTKCompatibility.h"
#include "vtkOpenGLState.h"       // for vtkOpenGLState
#include PPIRAY_VTK_OPENGL_HEADER // for GL enums

class vtkPPIRayPeelingStateRAII
{
public:
  explicit vtkPPIRayPeelingStateRAII(vtkOpenGLState* state)
    : State(state)
    , Viewport(state)
    , BlendFunc(state)
    , DepthMask(state)
    , DepthFunc(state)
    , ClearColor(state)
    , ColorMask(state)
    , Blend(state, GL_BLEND)
    , DepthTest(state, GL_DEPTH_TEST)
    , CullFace(state, GL_CULL_FACE)
    , Scissor(state, GL_SCISSOR_TEST)
  {
    state->vtkglGetIntegerv(GL_CULL_FACE_MODE, &this->CullFaceMode);
  }
  ~vtkPPIRayPeelingStateRAII() { this->State->vtkglCullFace(this->CullFaceMode); }

private:
  vtkPPIRayPeelingStateRAII(const vtkPPIRayPeelingStateRAII&) = delete;
  void operator=(const vtkPPIRayPeelingStateRAII&) = delete;

  vtkOpenGLState* State;
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglBlendFuncSeparate BlendFunc;
  vtkOpenGLState::ScopedglDepthMask DepthMask;
  vtkOpenGLState::ScopedglDepthFunc DepthFunc;
  vtkOpenGLState::ScopedglClearColor ClearColor;
  vtkOpenGLState::ScopedglColorMask ColorMask;
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable DepthTest;
  vtkOpenGLState::ScopedglEnableDisable CullFace;
  vtkOpenGLState::ScopedglEnableDisable Scissor;
  int CullFaceMode = GL_BACK;
};

#endif
