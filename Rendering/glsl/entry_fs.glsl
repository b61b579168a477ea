//VTK::System::Dec
// Entry and peel pass (Espinha & Celes 2005, Sec. 3.3): per pixel, the nearest
// front-facing boundary triangle
//  - strictly behind the previous layer's entry triangle (classic depth
//    peeling: the same face is never entered twice), and
//  - not before where the previous march left the mesh (minus a tolerance):
//    a ray that passed exactly through a boundary edge may already have
//    marched through the cell behind it, which must not be integrated twice.
// Along a ray, boundary crossings alternate between entering and leaving, so
// layer k is the k-th entry. The triangle id tells the march pass the cell and
// face the ray enters through.

in vec3 positionLocal;

uniform sampler2D previousLayerDepth; // depth of layer k-1 (unused for k = 0)
uniform sampler2D previousExit;       // ray parameter where march k-1 stopped
uniform sampler2D opaqueDepth;        // VTK's depth buffer: opaque geometry
uniform sampler2D accumulated;        // colour composited so far
uniform int firstLayer;
uniform float terminationAlpha;
uniform float exitTolerance;
uniform vec2 viewportSize;

out vec4 fragOutput0; // r: boundary triangle id + 1 (0: no entry)

//PPIRay::Ray::Impl

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = gl_FragCoord.z;
  if (depth >= texelFetch(opaqueDepth, pixel, 0).r ||
    texelFetch(accumulated, pixel, 0).a >= terminationAlpha)
  {
    discard;
  }
  if (firstLayer == 0)
  {
    vec3 origin, direction;
    pixelRay(2.0 * gl_FragCoord.xy / viewportSize - 1.0, origin, direction);
    float t = dot(positionLocal - origin, direction);
    if (depth <= texelFetch(previousLayerDepth, pixel, 0).r ||
      t < texelFetch(previousExit, pixel, 0).r - exitTolerance)
    {
      discard;
    }
  }
  fragOutput0 = vec4(float(gl_PrimitiveID + 1), 0.0, 0.0, 1.0);
}
