// Links against PPIRay::Rendering and creates the mapper and the reference
// renderer (PPIRay::Filters, its header in Filters/Reference/ in the build
// tree): proves the exported targets, headers and libraries are usable from
// another CMake project.
#include "vtkNew.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"
#include "vtkUnstructuredGridReferenceRenderer.h"

#include <iostream>

int main()
{
  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  vtkNew<vtkUnstructuredGridReferenceRenderer> reference;
  std::cout << mapper->GetClassName() << " Psi table " << mapper->GetPsiTableSize() << ", "
            << reference->GetClassName() << "\n";
  return mapper->GetPsiTableSize() > 0 ? 0 : 1;
}
