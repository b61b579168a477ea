//VTK::System::Dec
// Near-plane pass, fragments: the pixel's ray starts at the near plane inside
// this cell; its entry code (march_common_fs.glsl, enterPeel) comes with the
// vertices, made on the CPU (vtkPPIRayCellBuffers::AppendSection).

flat in float sectionCell;
out vec4 fragOutput0;

void main()
{
  fragOutput0 = vec4(sectionCell, 0.0, 0.0, 1.0);
}
