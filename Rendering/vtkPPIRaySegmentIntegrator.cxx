#include "vtkPPIRaySegmentIntegrator.h"

#include "ppirayMapperModes.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPreIntegrationTable.h"
#include "vtkPsiTable.h"
#include "vtkSetGet.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTimeStamp.h"

#include "piece_exact_fs.h"
#include "piece_ppi_fs.h"
#include "segment_average_fs.h"
#include "segment_full_fs.h"
#include "segment_split_fs.h"

namespace
{
// A texture sampled with (bi/tri)linear filtering, clamped at its edges.
void LinearClamped(vtkTextureObject* texture, vtkOpenGLRenderWindow* context)
{
  texture->SetContext(context);
  texture->SetMinificationFilter(vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetWrapR(vtkTextureObject::ClampToEdge);
}

// PARTIAL_PRE_INTEGRATION: the segment split at every control point, each
// piece by Moreland and Angel's Psi table (piece_ppi_fs.glsl).
class PsiTableIntegrator : public vtkPPIRaySegmentIntegrator
{
public:
  int GetIntegrationMode() const override { return ppiray::PartialPreIntegration; }
  std::string GetShaderCode() const override
  {
    return std::string(piece_ppi_fs) + segment_split_fs;
  }
  bool Update(vtkOpenGLRenderWindow* context, const Inputs& inputs, vtkObject*) override
  {
    if (this->Size == inputs.PsiTableSize)
    {
      return true;
    }
    const std::vector<float>& table = vtkPsiTable::GetTable(inputs.PsiTableSize);
    LinearClamped(this->Texture, context);
    this->Texture->Create2DFromRaw(
      inputs.PsiTableSize, inputs.PsiTableSize, 1, VTK_FLOAT, const_cast<float*>(table.data()));
    this->Size = inputs.PsiTableSize;
    return true;
  }
  void Bind(vtkShaderProgram* program, std::vector<vtkTextureObject*>& active) override
  {
    this->Texture->Activate();
    program->SetUniformi("psiTable", this->Texture->GetTextureUnit());
    program->SetUniformf("psiTableSize", static_cast<float>(this->Size));
    active.push_back(this->Texture);
  }
  size_t GetGPUBytes() const override
  {
    return static_cast<size_t>(this->Size) * this->Size * sizeof(float);
  }
  void ReleaseGraphicsResources(vtkWindow* window) override
  {
    this->Texture->ReleaseGraphicsResources(window);
    this->Size = 0;
  }

private:
  vtkNew<vtkTextureObject> Texture;
  int Size = 0;
};

// EXACT_LINEAR: the same split, Psi in closed form in the shader.
class ExactLinearIntegrator : public vtkPPIRaySegmentIntegrator
{
public:
  int GetIntegrationMode() const override { return ppiray::ExactLinear; }
  std::string GetShaderCode() const override
  {
    return std::string(piece_exact_fs) + segment_split_fs;
  }
};

// AVERAGE_COLOR: the whole segment with the mean of its end colours.
class AverageColorIntegrator : public vtkPPIRaySegmentIntegrator
{
public:
  int GetIntegrationMode() const override { return ppiray::AverageColor; }
  std::string GetShaderCode() const override { return segment_average_fs; }
};

// FULL_PRE_INTEGRATION: the whole segment by one lookup in the 3D table over
// (s_front, s_back, length), rebuilt when the transfer function, the field's
// range or the longest segment changes.
class FullTableIntegrator : public vtkPPIRaySegmentIntegrator
{
public:
  int GetIntegrationMode() const override { return ppiray::FullPreIntegration; }
  std::string GetShaderCode() const override { return segment_full_fs; }
  bool Update(vtkOpenGLRenderWindow* context, const Inputs& inputs, vtkObject* reporter) override
  {
    const int n = inputs.PreIntegrationTableSize;
    if (this->Bytes && this->Table->GetScalarSize() == n &&
        this->Time.GetMTime() > inputs.SourceTime)
    {
      return true;
    }
    this->Table->Build(inputs.ControlPoints, inputs.FieldRange[0], inputs.FieldRange[1],
      inputs.MaximumSegmentLength, n, n);
    this->Shift = inputs.FieldShift;
    LinearClamped(this->Texture, context);
    if (!this->Texture->Create3DFromRaw(
          n, n, n, 4, VTK_FLOAT, const_cast<float*>(this->Table->GetTable().data())))
    {
      vtkErrorWithObjectMacro(
        reporter, "Could not upload the " << n << "^3 pre-integration table.");
      this->Bytes = 0;
      return false;
    }
    this->Bytes = this->Table->GetTable().size() * sizeof(float);
    this->Time.Modified();
    return true;
  }
  void Bind(vtkShaderProgram* program, std::vector<vtkTextureObject*>& active) override
  {
    this->Texture->Activate();
    program->SetUniformi("preIntegrationTable", this->Texture->GetTextureUnit());
    active.push_back(this->Texture);
    const double* range = this->Table->GetScalarRange();
    const float scalarRange[2] = { static_cast<float>(range[0] - this->Shift),
      static_cast<float>(range[1] - this->Shift) };
    const float size[3] = { static_cast<float>(this->Table->GetScalarSize()),
      static_cast<float>(this->Table->GetScalarSize()),
      static_cast<float>(this->Table->GetLengthSize()) };
    program->SetUniform2f("tableScalarRange", scalarRange);
    program->SetUniformf("tableMaximumLength", static_cast<float>(this->Table->GetMaximumLength()));
    program->SetUniform3f("tableSize", size);
  }
  size_t GetGPUBytes() const override { return this->Bytes; }
  double GetTableBuildTime() const override { return this->Table->GetBuildTime(); }
  void ReleaseGraphicsResources(vtkWindow* window) override
  {
    this->Texture->ReleaseGraphicsResources(window);
    this->Bytes = 0;
  }

private:
  vtkNew<vtkPreIntegrationTable> Table;
  vtkNew<vtkTextureObject> Texture;
  double Shift = 0.0;
  size_t Bytes = 0;
  vtkTimeStamp Time;
};
}

//------------------------------------------------------------------------------
std::unique_ptr<vtkPPIRaySegmentIntegrator> vtkPPIRaySegmentIntegrator::New(int integrationMode)
{
  switch (integrationMode)
  {
    case ppiray::ExactLinear:
      return std::unique_ptr<vtkPPIRaySegmentIntegrator>(new ExactLinearIntegrator);
    case ppiray::AverageColor:
      return std::unique_ptr<vtkPPIRaySegmentIntegrator>(new AverageColorIntegrator);
    case ppiray::FullPreIntegration:
      return std::unique_ptr<vtkPPIRaySegmentIntegrator>(new FullTableIntegrator);
    default:
      return std::unique_ptr<vtkPPIRaySegmentIntegrator>(new PsiTableIntegrator);
  }
}
