/**
 * @file   PPIRayGLSL.h
 * @brief  the shaders' own GLSL functions compiled as C++, for tests
 *
 * GLM gives C++ GLSL's vector types; this header gives the few built-in
 * functions GLSL declares for scalars with GLSL's implicit conversions (a
 * double literal passed where GLSL reads a float). A test includes a .glsl
 * file of functions (no uniforms) inside a namespace after
 * PPIRAY_GLSL_SCALAR_BUILTINS(T) and the vector aliases, with `out`
 * defined away (an `out float x[2]` parameter is then a C++ array
 * parameter); `#define float double` around a second inclusion runs the
 * same code in double. TestRayCubicPrecision shows the use.
 */
#ifndef PPIRayGLSL_h
#define PPIRayGLSL_h

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

#define PPIRAY_GLSL_SCALAR_BUILTINS(T)                                                             \
  inline T abs(T x)                                                                                \
  {                                                                                                \
    return std::abs(x);                                                                            \
  }                                                                                                \
  inline T sqrt(T x)                                                                               \
  {                                                                                                \
    return std::sqrt(x);                                                                           \
  }                                                                                                \
  inline T min(T a, T b)                                                                           \
  {                                                                                                \
    return std::min(a, b);                                                                         \
  }                                                                                                \
  inline T max(T a, T b)                                                                           \
  {                                                                                                \
    return std::max(a, b);                                                                         \
  }                                                                                                \
  inline T clamp(T x, T lo, T hi)                                                                  \
  {                                                                                                \
    return std::min(std::max(x, lo), hi);                                                          \
  }

#endif
