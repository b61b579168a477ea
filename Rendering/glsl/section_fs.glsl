//VTK::System::Dec
// Near-plane pass, fragments: the pixel's ray starts at the near plane inside
// this cell; written as -(cell + 1) where the entry pass writes a boundary
// triangle id + 1 (march_common_fs.glsl, enterPeel).

flat in float sectionCell;
out vec4 fragOutput0;

void main()
{
  fragOutput0 = vec4(-(sectionCell + 1.0), 0.0, 0.0, 1.0);
}
