//VTK::System::Dec
// Near-plane pass, vertices: the sections of the cells the camera's near
// plane cuts (vtkPPIRayCellBuffers::PlaneSection), in the mesh's local
// frame. They lie on the near plane, where clipping would cut them, so they
// are drawn at mid depth (no depth test: the sections of a mesh do not overlap).

in vec4 vertexMC; // xyz: the point; w: the entry code of the cell it is a section of
uniform mat4 localToClip;
flat out float sectionCell;

void main()
{
  vec4 clip = localToClip * vec4(vertexMC.xyz, 1.0);
  gl_Position = vec4(clip.xy, 0.0, clip.w);
  sectionCell = vertexMC.w;
}
