// Registers vtkUnstructuredGridConvexify with VTK's object factory when this
// library is loaded, under its own class name, so that
// vtkObjectFactory::CreateInstance("vtkUnstructuredGridConvexify") makes one
// where nothing links this (GPL) module: the mapper's NON_CONVEX_CONVEXIFY
// without a Convexifier set (vtkUnstructuredGridGPURayCastMapper), ParaView's
// "Non-Convex Mode" with the PPIRayConvexify plugin loaded.
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkUnstructuredGridConvexify.h"
#include "vtkVersion.h"

namespace
{
vtkObject* MakeConvexify()
{
  return vtkUnstructuredGridConvexify::New();
}

class ConvexifyFactory : public vtkObjectFactory
{
public:
  static ConvexifyFactory* New()
  {
    auto* result = new ConvexifyFactory;
    result->InitializeObjectBase();
    return result;
  }
  vtkTypeMacro(ConvexifyFactory, vtkObjectFactory);
  const char* GetVTKSourceVersion() override { return VTK_SOURCE_VERSION; }
  const char* GetDescription() override { return "PPIRay::Convexify"; }

protected:
  ConvexifyFactory()
  {
    this->RegisterOverride("vtkUnstructuredGridConvexify", "vtkUnstructuredGridConvexify",
      "imaginary tetrahedra filling the convex hull (CGAL)", 1, MakeConvexify);
  }
};

// Registered for the library's lifetime.
struct Registration
{
  vtkNew<ConvexifyFactory> Factory;
  Registration() { vtkObjectFactory::RegisterFactory(this->Factory); }
  ~Registration() { vtkObjectFactory::UnRegisterFactory(this->Factory); }
} registration;
}
