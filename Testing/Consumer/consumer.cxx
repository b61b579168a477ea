// Links against PPIRay::Rendering and creates the mapper: proves the exported
// targets, headers and libraries are usable from another CMake project.
#include "vtkNew.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <iostream>

int main()
{
  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  std::cout << mapper->GetClassName() << " Psi table " << mapper->GetPsiTableSize() << "\n";
  return mapper->GetPsiTableSize() > 0 ? 0 : 1;
}
