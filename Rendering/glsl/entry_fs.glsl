//VTK::System::Dec
#if __VERSION__ < 330
// uintBitsToFloat (the entry code, march_common_fs.glsl)
#extension GL_ARB_shader_bit_encoding : require
#endif
// Entry and peel pass (Espinha & Celes 2005, Sec. 3.3): per pixel, the nearest
// front-facing boundary triangle strictly behind the previous layer's entry
// triangle (classic depth peeling: the same face is never entered twice).
// Along a ray, boundary crossings alternate between entering and leaving, so
// layer k is the k-th entry. The triangle id tells the march pass the cell and
// face the ray enters through.
//
// A layer may begin before where the previous march left the mesh: a ray
// through a boundary edge has already marched through the cell behind it,
// and across a fault the two sides' boundary faces (non-planar quadrilaterals
// split along different diagonals) cross each other. The march starts such a
// layer at the previous exit (march_common_fs.glsl, enterPeel), so nothing is
// integrated twice and nothing behind the exit is dropped.
//
// Like opaque geometry, a clipping plane that closes the ray ends its peels:
// an entry past the kept part of the ray is no entry.

uniform sampler2D previousLayerDepth; // depth of layer k-1 (unused for k = 0)
uniform sampler2D opaqueDepth;        // VTK's depth buffer: opaque geometry
uniform sampler2D accumulated;        // colour composited so far
uniform int firstLayer;
uniform float terminationAlpha;
uniform vec2 viewportSize;
in vec3 localPosition;

//PPIRay::Ray::Impl

out vec4 fragOutput0; // r: the entry code of the boundary triangle (0: no entry)

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = gl_FragCoord.z;
  if (depth >= texelFetch(opaqueDepth, pixel, 0).r ||
    texelFetch(accumulated, pixel, 0).a >= terminationAlpha)
  {
    discard;
  }
  if (firstLayer == 0 && depth <= texelFetch(previousLayerDepth, pixel, 0).r)
  {
    discard;
  }
  if (numberOfClippingPlanes > 0)
  {
    vec3 origin, direction;
    pixelRay(2.0 * gl_FragCoord.xy / viewportSize - 1.0, origin, direction);
    if (dot(localPosition - origin, direction) > keptRange(origin, direction).y)
    {
      discard;
    }
  }
  fragOutput0 = vec4(uintBitsToFloat(uint(2 * gl_PrimitiveID) + 0x00800000u), 0.0, 0.0, 1.0);
}
