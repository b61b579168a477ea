//VTK::System::Dec
// Entry and peel pass, vertex stage: boundary triangles in the mesh's local
// frame (coordinates relative to the centre of its bounds) to clip space.

in vec3 vertexMC;
uniform mat4 localToClip;
out vec3 localPosition;

void main()
{
  gl_Position = localToClip * vec4(vertexMC, 1.0);
  localPosition = vertexMC;
}
